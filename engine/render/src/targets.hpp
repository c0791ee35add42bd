// The frame's render targets (private to engine/render).
#pragma once

#include "halfvec/gl/objects.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/render/renderer.hpp"

namespace hv::render {

struct Renderer::Targets {
  int width = 0, height = 0;
  gl::Texture base_cavity;  // SRGB8_ALPHA8
  gl::Texture material;     // RGBA8: metallic, roughness, model id
  gl::Texture normal;       // RG16_SNORM octahedral
  gl::Texture depth;        // DEPTH_COMPONENT32F reversed Z
  gl::Texture hdr;          // RGBA16F accumulation
  gl::Texture ldr;          // RGBA8 output
  gl::Framebuffer gbuffer;  // base, material, normal, hdr + depth
  gl::Framebuffer output;   // ldr
};

// The environment's GPU resources (uploaded IBL bake).
struct Renderer::Environment {
  gl::Texture radiance, irradiance, env_brdf;
  gl::Buffer block;
  gl::Sampler trilinear;
  bool present = false;
  BakeTimings timings;
};

}  // namespace hv::render

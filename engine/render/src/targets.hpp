// The frame's render targets and the pass objects (private to engine/render).
#pragma once

#include "halfvec/gl/objects.hpp"
#include "halfvec/render/renderer.hpp"
#include "passes.hpp"
#include "shadow_pass.hpp"

namespace hv::render {

struct Renderer::Targets {
  int width = 0, height = 0;
  gl::Texture base_cavity;  // SRGB8_ALPHA8
  gl::Texture material;     // RGBA8: metallic, roughness high byte, model id, roughness low byte
  gl::Texture normal;       // RG16_SNORM octahedral
  gl::Texture depth;        // DEPTH_COMPONENT32F reversed Z
  gl::Texture coat;         // RGBA16_SNORM coat normal, weight, roughness (clear-coat scenes only)
  gl::Texture hdr;          // RGBA16F accumulation
  gl::Texture ldr;          // RGBA8 output
  gl::Texture floor;        // RGBA16F scratch of the floor pass (created when first needed)
  gl::Framebuffer gbuffer;  // base, material, normal, hdr (, coat) + depth
  gl::Framebuffer output;   // ldr
  gl::Framebuffer forward;  // hdr + depth: the blended surfaces (depth tested, not written)
  GBufferView gbufferView() const {
    return {base_cavity.id(), material.id(), normal.id(), depth.id(), coat ? coat.id() : 0u};
  }
};

// The passes that keep resources from frame to frame, and the scene's environment.
struct Renderer::Passes {
  LightCulling culling;
  LightPass light;
  ShadowMaps shadows;
  ShadowMaskPass shadow_mask;
  AoPass ao;
  ForwardPass forward;
  std::unique_ptr<GpuEnvironment> environment;
};

}  // namespace hv::render

// The shadow mask pass (passes.hpp, ShadowMaskPass): settings.shadow_resolution half. The
// shadowed lights' visibility once per 2x2 pixels, one dispatch layer per light, then resolved
// to every pixel for the light pass (shaders/common/shadow_mask.glsl).
#include <algorithm>

#include "halfvec/scene/scene.hpp"
#include "passes.hpp"
#include "pipeline_state.hpp"
#include "shadow_pass.hpp"

namespace hv::render {

// The mask's first layers are the directional lights' (shadowMaskLayer).
static_assert(HV_SHADOW_MASK_SUN_LAYERS == kMaxDirectionalLights);

ShadowMaskPass::Output ShadowMaskPass::run(const PassContext& ctx, const Input& in, int width,
                                           int height) {
  gl::ScopedPass pass(ctx.timer, "shadow_mask");
  applyState(PipelineState{});
  const int w = (width + 1) / 2, h = (height + 1) / 2;
  // Layers: the sun layers, then one per cube the lights use (at least one, so the light pass
  // always samples a complete texture).
  const int cubes = int(std::min<size_t>(in.mapped.size(), HV_SHADOW_MASK_MAX_CUBES));
  const int layers = HV_SHADOW_MASK_SUN_LAYERS + std::max(cubes, 1);
  if (width != width_ || height != height_ || layers != layers_ || !mask_) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    mask_ = gl::Texture(id, "shadow mask (visibility, a layer per shadowed light)");
    glTextureStorage3D(id, 1, GL_R8, w, h, layers);
    geometry_ = gl::createTexture2D("shadow mask geometry (inverse view distance, normal)",
                                    GL_RGBA16F, w, h);
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    resolved_ = gl::Texture(id, "shadow mask, resolved (visibility per pixel, a layer per light)");
    glTextureStorage3D(id, 1, GL_R8, width, height, layers);
    width_ = width;
    height_ = height;
    layers_ = layers;
  }
  if (in.mapped.empty()) return {resolved_.id()};
  if (in.mapped.size() > lights_capacity_) {
    lights_capacity_ = std::max<size_t>(in.mapped.size(), 8);
    lights_ = gl::createBuffer("shadow mask lights", lights_capacity_ * sizeof(uint32_t));
  }
  glNamedBufferSubData(lights_.id(), 0, GLsizeiptr(in.mapped.size() * sizeof(uint32_t)),
                       in.mapped.data());
  gl::PassBindings b(kPassSlots, "shadow mask");
  // Step 1: the visibility at one pixel per 2x2 block, a dispatch layer per light, and the
  // texels' geometry.
  const GLuint mask = ctx.programs.get(
      {"shadow mask", {{GL_COMPUTE_SHADER, "passes/shadow_mask.comp"}}, in.defines});
  b.use(mask);
  bindGBuffer(b, in.gbuffer, ctx.nearest);
  b.storage(HV_BINDING_LIGHTS, in.lights);
  b.storage(HV_BINDING_SHADOW_MASK_LIGHTS, lights_.id());
  b.image(HV_IMAGE_SHADOW_MASK, mask_.id(), GL_WRITE_ONLY, GL_R8, 0, GL_TRUE);
  b.image(HV_IMAGE_SHADOW_MASK_GEOMETRY, geometry_.id(), GL_WRITE_ONLY, GL_RGBA16F);
  bindLightTables(b, nullptr, 0, &in.shadows);
  // 8 x 8 invocations of 4 texels a column each (shadow_mask.comp).
  glDispatchCompute(GLuint((w + 7) / 8), GLuint((h + 31) / 32), GLuint(in.mapped.size()));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  // Step 2: every pixel's visibility of every light, upsampled (shadow_resolve.comp), in 8 x 8
  // invocations of 4 pixels a column each; the workgroups with a pixel that no texel holds are
  // listed for step 3.
  const GLuint gx = GLuint((width + 7) / 8), gy = GLuint((height + 31) / 32);
  if (size_t(gx) * gy > fallback_capacity_) {
    fallback_capacity_ = size_t(gx) * gy;
    fallback_ = gl::createBuffer("shadow resolve fallback (indirect dispatch, workgroups)",
                                 (4 + fallback_capacity_) * sizeof(uint32_t));
  }
  const uint32_t reset[4] = {0, 0, 1, 0};  // no workgroup yet: a dispatch of none
  glNamedBufferSubData(fallback_.id(), 0, sizeof reset, reset);
  b.storage(HV_BINDING_SHADOW_FALLBACK, fallback_.id());
  b.texture(HV_UNIT_SHADOW_MASK, mask_.id(), ctx.nearest);
  b.texture(HV_UNIT_SHADOW_MASK_GEOMETRY, geometry_.id(), ctx.nearest);
  b.image(HV_IMAGE_SHADOW_MASK, resolved_.id(), GL_WRITE_ONLY, GL_R8, 0, GL_TRUE);
  // The resolve (HV_SHADOW_RESOLVE_FALLBACK 0) or its fallback (1), bound.
  const auto useResolve = [&](const char* fallback) {
    gl::DefineSet defines = in.defines;
    defines.push_back({"HV_SHADOW_RESOLVE_FALLBACK", fallback});
    const GLuint resolve = ctx.programs.get(
        {"shadow resolve", {{GL_COMPUTE_SHADER, "passes/shadow_resolve.comp"}}, defines});
    b.use(resolve);
    glProgramUniform1ui(resolve, HV_LOC_SHADOW_MASK_LIGHTS, GLuint(in.mapped.size()));
  };
  useResolve("0");
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  // Step 3: the maps' lookup in the listed workgroups alone (an indirect dispatch).
  useResolve("1");
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, fallback_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  return {resolved_.id()};
}

}  // namespace hv::render

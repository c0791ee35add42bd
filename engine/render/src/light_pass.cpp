// The light pass (compute, per pixel). In: G-buffer, lights, per-tile light lists (or none: brute
// force). Out: direct light added into the HDR target.
#include <algorithm>
#include <string>

#include "ltc_textures.hpp"
#include "passes.hpp"
#include "pipeline_state.hpp"
#include "shadow_pass.hpp"

namespace hv::render {

void bindLightTables(gl::PassBindings& b, std::unique_ptr<LtcTextures>* ltc,
                     GLuint error_table_unit, const ShadowMaps* shadows) {
  if (ltc) {
    if (!*ltc) *ltc = std::make_unique<LtcTextures>();
    (*ltc)->bind(b);
    if (error_table_unit) (*ltc)->bindErrorTable(b, error_table_unit);
  }
  if (shadows) {  // ShadowMaps binds its two units itself (shadow_pass.cpp): declared here
    shadows->bind();
    b.declareTexture(HV_UNIT_SHADOW_DEPTH);
    b.declareTexture(HV_UNIT_SHADOW_COMPARE);
    // The directional lights' orthographic maps and their frames.
    b.texture(HV_UNIT_SUN_SHADOW_DEPTH, shadows->sunMaps(), shadows->rawSampler());
    b.texture(HV_UNIT_SUN_SHADOW_COMPARE, shadows->sunMaps(), shadows->compareSampler());
    b.uniform(HV_UBO_SUN_SHADOWS, shadows->sunBlock());
  }
}

// The tiled light pass reads the lights and the tile index list through buffer textures
// (HV_LIGHTS_TEXTURE) when they fit GL_MAX_TEXTURE_BUFFER_SIZE: texelFetch gives the
// implementation a vector gather, where an SSBO read indexed by loaded data is a per-lane load on a
// SIMD CPU implementation (docs/lights.md, "Tiled culling"). Otherwise it reads the SSBOs.
void LightPass::run(const PassContext& ctx, const FrameBlock& frame, const Input& in, GLuint hdr) {
  gl::ScopedPass pass(ctx.timer, "light");
  applyState(PipelineState{});
  if (in.light_count == 0) return;
  const bool tiled = bool(in.tiles);
  GLint gl_max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &gl_max_texels);
  size_t max_texels = size_t(std::max(gl_max_texels, 0));
  if (in.texel_limit > 0) max_texels = std::min(max_texels, in.texel_limit);
  const bool use_textures = tiled && in.light_count * 4 <= max_texels &&
                            HV_TILE_LIST_HEADER_UINTS + in.tiles.capacity <= max_texels;
  gl::DefineSet defines = in.defines;
  defines.push_back({"HV_LIGHTS_TEXTURE", use_textures ? "1" : "0"});
  if (in.probe != LightPassProbe::Shade) {
    defines.push_back({"HV_LIGHT_PROBE", std::to_string(static_cast<int>(in.probe))});
  }
  const GLuint prog =
      ctx.programs.get({"light", {{GL_COMPUTE_SHADER, "passes/light_shade.comp"}}, defines});
  gl::PassBindings b(kPassSlots, "light");
  b.use(prog);
  bindGBuffer(b, in.gbuffer, ctx.nearest);
  b.image(HV_IMAGE_HDR, hdr, GL_READ_WRITE, GL_RGBA16F);
  b.storage(HV_BINDING_LIGHTS, in.lights);
  if (tiled) {
    b.storage(HV_BINDING_TILE_RANGES, in.tiles.ranges);
    b.storage(HV_BINDING_TILE_INDICES, in.tiles.indices);
    b.storage(HV_BINDING_TILE_TYPES, in.tiles.types);
  }
  if (use_textures) {
    if (!light_texels_) {
      GLuint ids[2] = {0, 0};
      glCreateTextures(GL_TEXTURE_BUFFER, 2, ids);
      light_texels_ = gl::Texture(ids[0], "lights (buffer texture)");
      tile_index_texels_ = gl::Texture(ids[1], "tile light indices (buffer texture)");
    }
    // Re-pointed every frame: either buffer may have been re-created (scene edit, list growth).
    glTextureBuffer(light_texels_.id(), GL_RGBA32UI, in.lights);  // uints: light_shade.comp
    glTextureBuffer(tile_index_texels_.id(), GL_R32UI, in.tiles.indices);
    b.texture(HV_UNIT_LIGHT_TEXELS, light_texels_.id());
    b.texture(HV_UNIT_TILE_INDEX_TEXELS, tile_index_texels_.id());
  }
  bindLightTables(b, in.ltc ? &ltc_ : nullptr, in.error_table ? HV_UNIT_ERROR_TABLE : 0,
                  in.shadows);
  if (in.mask.mask) {  // shadow_resolution half: the resolved mask (shadow_mask.glsl)
    b.texture(HV_UNIT_SHADOW_MASK, in.mask.mask, ctx.nearest);
  }
  glDispatchCompute(frame.viewport.z, (frame.viewport.w + kLightGroupTiles - 1) / kLightGroupTiles,
                    1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace hv::render

// Light culling (compute: per tile bounds, per light count/fill, one scan) and the light pass
// (compute, per pixel).
// In: depth, G-buffer, lights. Out: per-tile light lists; direct light added into the HDR target.
#include <algorithm>
#include <string>

#include "ltc_textures.hpp"
#include "pipeline_state.hpp"
#include "halfvec/render/renderer.hpp"
#include "targets.hpp"

namespace hv::render {

namespace {
constexpr size_t kTileHeaderUints = 4;  // counter + padding before the index array
// Upper bound of the (tile, light) pairs the culling can find: the sum of the lights' tile
// rectangles (sphereTileRect, the function the GPU runs), each widened by one tile on every side
// so that rounding differences between the two compilers cannot make it smaller than the GPU's.
size_t listBound(const std::vector<glm::vec4>& spheres, const FrameBlock& frame) {
  const glm::vec2 scale(frame.proj[0][0], frame.proj[1][1]);
  const glm::vec2 viewport(frame.viewport.x, frame.viewport.y);
  const glm::ivec2 tiles(frame.viewport.z, frame.viewport.w);
  const glm::vec2 tile_px(kTileSize, kTileHeight);
  size_t bound = 0;
  for (const glm::vec4& s : spheres) {
    const glm::vec3 c = glm::vec3(frame.view * glm::vec4(glm::vec3(s), 1.0f));
    glm::ivec4 r;
    if (!glsl::sphereTileRect(c, s.w, scale, frame.near_params.x, viewport, tiles, tile_px, r)) {
      continue;
    }
    const glm::ivec2 lo = glm::max(glm::ivec2(r.x, r.y) - 1, glm::ivec2(0));
    const glm::ivec2 hi = glm::min(glm::ivec2(r.z, r.w) + 1, tiles - 1);
    bound += size_t(hi.x - lo.x + 1) * size_t(hi.y - lo.y + 1);
  }
  return bound;
}
}  // namespace

void Renderer::growTileList(size_t need) {
  tile_capacity_ = std::max(tile_capacity_, need + need / 4);  // headroom: fewer reallocations
  tile_indices_ = gl::createBuffer("tile light indices",
                                   (kTileHeaderUints + tile_capacity_) * sizeof(uint32_t));
}

// Tiled culling in four dispatches (shaders/passes/light_cull.comp; docs/lights.md): tile surface
// bounds, per-light count, prefix sum, per-light fill. The work is tiles + lights + the (tile,
// light) pairs that touch, instead of tiles x lights. No cap on a tile's list: the index list is
// sized before the fill from an upper bound computed on the CPU (listBound: the lights' tile
// rectangles, which contain every pair the GPU can find), so nothing waits for the GPU mid-frame.
// Only when that bound exceeds setTileListBoundLimit (32 Mi entries, 128 MiB, by default) is the
// exact total read back between the scan and the fill (a pipeline stall on a GPU) to size the
// list to the need instead.
void Renderer::cullLightsPass(FrameBlock& frame) {
  gl::ScopedPass pass(timer_, "light_cull");
  applyState(PipelineState{});
  Targets& t = *targets_;
  const size_t tiles = size_t(frame.viewport.z) * frame.viewport.w;
  if (!tile_ranges_ || tiles > tile_buffers_tiles_) {
    tile_ranges_ = gl::createBuffer("tile light ranges", tiles * 2 * sizeof(uint32_t));
    tile_types_ = gl::createBuffer("tile light type split", tiles * 2 * sizeof(uint32_t));
    tile_bounds_ = gl::createBuffer("tile surface bounds", tiles * 2 * 4 * sizeof(float));
    tile_counters_ = gl::createBuffer("tile light counters", tiles * 3 * sizeof(uint32_t));
    tile_buffers_tiles_ = tiles;
  }
  if (!tile_indices_) growTileList(std::max<size_t>(tiles * 16, 1 << 16));
  // Size the list before anything runs, from the CPU bound when it is small enough.
  const size_t bound = listBound(gpu_->lightCullSpheres(), frame);
  const bool bounded = bound <= tile_bound_limit_;
  if (bounded && bound > tile_capacity_) growTileList(bound);
  auto stage = [&](const char* name, const char* value) {
    return programs_.get(
        {name, {{GL_COMPUTE_SHADER, "passes/light_cull.comp"}}, {{"HV_CULL_STAGE", value}}});
  };
  const GLuint bounds_prog = stage("light_cull_bounds", "0");
  const GLuint lights_prog = stage("light_cull_lights", "1");
  const GLuint scan_prog = stage("light_cull_scan", "2");
  const GLint phase_loc = glGetUniformLocation(lights_prog, "u_cull_phase");
  const uint32_t lights = frame.counts.x;
  const GLuint light_groups = (lights + 63) / 64;

  const uint32_t zero = 0;
  glClearNamedBufferSubData(tile_counters_.id(), GL_R32UI, 0, tiles * 3 * sizeof(uint32_t),
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, gpu_->lightBuffer());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, tile_counters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, tile_ranges_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, tile_indices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, tile_types_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, tile_bounds_.id());

  // 1. Surface bounds per tile.
  glUseProgram(bounds_prog);
  glBindTextureUnit(3, t.depth.id());
  glBindSampler(3, nearest_.id());
  glDispatchCompute(frame.viewport.z, frame.viewport.w, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  // 2. Count the (tile, light) pairs per tile and light type.
  glUseProgram(lights_prog);
  glProgramUniform1ui(lights_prog, phase_loc, 0u);
  if (light_groups > 0) glDispatchCompute(light_groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  // 3. Prefix sum: exact ranges, sorted by type.
  glUseProgram(scan_prog);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  if (!bounded) {  // the bound is too loose to allocate: read the exact total back (a stall)
    uint32_t total = 0;
    glGetNamedBufferSubData(tile_indices_.id(), 0, sizeof total, &total);
    ++list_readbacks_;
    if (total > tile_capacity_) {  // grow to the need plus headroom, keep the header
      growTileList(total);
      glNamedBufferSubData(tile_indices_.id(), 0, sizeof total, &total);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, tile_indices_.id());
    }
  }
  if (frame.counts.y != tile_capacity_) {  // the list was created or grown: tell the shaders
    frame.counts.y = static_cast<uint32_t>(tile_capacity_);
    glNamedBufferSubData(frame_ubo_.id(), 0, sizeof frame, &frame);
  }
  // 4. Fill: the same program writes each pair into the slot the scan reserved.
  glUseProgram(lights_prog);
  glProgramUniform1ui(lights_prog, phase_loc, 1u);
  if (light_groups > 0) glDispatchCompute(light_groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindSampler(3, 0);
  glUseProgram(0);
}

// The tiled light pass reads the lights and the tile index list through buffer textures
// (HV_LIGHTS_TEXTURE) when they fit GL_MAX_TEXTURE_BUFFER_SIZE: texelFetch gives the
// implementation a vector gather, where an SSBO read indexed by loaded data is a per-lane load on a
// SIMD CPU implementation (llvmpipe: ~3x slower loop, measured). Otherwise it reads the SSBOs.
void Renderer::lightPass(const FrameBlock& frame) {
  gl::ScopedPass pass(timer_, "light");
  applyState(PipelineState{});
  Targets& t = *targets_;
  if (gpu_->lightCount() == 0) return;
  const bool tiled = scene_->settings.culling == Culling::Tiled && tile_indices_;
  GLint gl_max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &gl_max_texels);
  size_t max_texels = size_t(std::max(gl_max_texels, 0));
  if (light_texel_limit_ > 0) max_texels = std::min(max_texels, light_texel_limit_);
  const bool use_textures = tiled && gpu_->lightCount() * 4 <= max_texels &&
                            kTileHeaderUints + tile_capacity_ <= max_texels;
  gl::DefineSet defines = lightingDefines();
  defines.push_back({"HV_LIGHTS_TEXTURE", use_textures ? "1" : "0"});
  if (light_probe_ != LightPassProbe::Shade) {
    defines.push_back({"HV_LIGHT_PROBE", std::to_string(static_cast<int>(light_probe_))});
  }
  const GLuint prog =
      programs_.get({"light", {{GL_COMPUTE_SHADER, "passes/light_shade.comp"}}, defines});
  glUseProgram(prog);
  const GLuint inputs[4] = {t.base_cavity.id(), t.material.id(), t.normal.id(), t.depth.id()};
  for (GLuint u = 0; u < 4; ++u) {
    glBindTextureUnit(u, inputs[u]);
    glBindSampler(u, nearest_.id());
  }
  glBindImageTexture(0, t.hdr.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, gpu_->lightBuffer());
  if (tile_indices_) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, tile_ranges_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, tile_indices_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, tile_types_.id());
  }
  if (use_textures) {
    if (!light_texels_) {
      GLuint ids[2] = {0, 0};
      glCreateTextures(GL_TEXTURE_BUFFER, 2, ids);
      light_texels_ = gl::Texture(ids[0], "lights (buffer texture)");
      tile_index_texels_ = gl::Texture(ids[1], "tile light indices (buffer texture)");
    }
    // Re-pointed every frame: either buffer may have been re-created (scene edit, list growth).
    glTextureBuffer(light_texels_.id(), GL_RGBA32F, gpu_->lightBuffer());
    glTextureBuffer(tile_index_texels_.id(), GL_R32UI, tile_indices_.id());
    glBindTextureUnit(4, light_texels_.id());
    glBindTextureUnit(5, tile_index_texels_.id());
  }
  const bool ltc = lightPassNeedsLtc();
  if (ltc) {
    if (!ltc_) ltc_ = std::make_unique<LtcTextures>();
    ltc_->bind();
  }
  glDispatchCompute(frame.viewport.z, (frame.viewport.w + kLightGroupTiles - 1) / kLightGroupTiles,
                    1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  if (ltc) LtcTextures::unbind();
  for (GLuint u = 0; u < 4; ++u) glBindSampler(u, 0);
  if (use_textures) {
    glBindTextureUnit(4, 0);
    glBindTextureUnit(5, 0);
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
  glUseProgram(0);
}

// The light program reads the LTC table (lights.glsl HV_LTC_TABLE) when a light type it compiles
// shades its specular with it.
bool Renderer::lightPassNeedsLtc() const {
  const RenderSettings& s = key_.settings;
  return (key_.sphere_lights && s.sphere_specular == SphereSpecular::Ltc) ||
         (key_.tube_lights && s.tube_specular == TubeSpecular::Ltc);
}

}  // namespace hv::render

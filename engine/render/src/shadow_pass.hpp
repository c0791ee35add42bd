// The shadow-map pass (private to engine/render): renders the omnidirectional maps of the
// shadowed lights into the atlas (halfvec/render/shadows.hpp) when a light or a caster changed,
// keeps them otherwise, and tells the light pass where each light's map is (GpuLight.shadow_cube).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "halfvec/gl/bindings.hpp"
#include "halfvec/gl/objects.hpp"
#include "halfvec/render/gpu_scene.hpp"
#include "halfvec/render/shadows.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::render {

struct PassContext;

// hv::log::warn (shadow_maps.cpp: halfvec/gl/log.hpp's namespace `log` hides the GLSL log() of
// the shading headers included here).
void logShadowWarning(const std::string& message);

class ShadowMaps {
 public:
  struct Input {
    const Scene& scene;
    const GpuScene& gpu;
    int map_size = 1024;        // settings.shadow_map_size
    size_t lights_version = 0;  // changes whenever GpuScene::updateLights re-uploaded the lights
    // settings.shadow_resolution half: the shadow mask's layers bound the lights with a cube
    // (HV_SHADOW_MASK_MAX_CUBES) besides the atlas.
    bool mask = false;
  };
  struct Stats {
    size_t maps = 0;      // lights with a map this frame
    size_t rendered = 0;  // of them, re-rendered this frame (the others were cached)
    std::vector<size_t> over_budget;
    std::vector<uint32_t> mapped;  // the lights with a map: cubes in cube order, then the suns
  };
  // Assigns the cubes, writes each light's shadow_cube (cube + 1, 0 = none) into the GPU light
  // buffer, and renders the cubes whose light or casters changed since they were last rendered.
  Stats run(const PassContext& ctx, const Input& in);
  // Forgets every cube (a new scene: other casters).
  void invalidate() { cubes_.clear(); }
  // Binds the atlas on HV_UNIT_SHADOW_DEPTH (raw distances) and HV_UNIT_SHADOW_COMPARE (depth
  // comparison) for the light pass; unbind releases both units.
  void bind() const;
  static void unbind();
  // The directional lights' maps (a 2D depth array), its two samplers and its uniform block
  // (GpuSunShadow per layer), for gl::PassBindings::texture / uniform.
  GLuint sunMaps() const { return sun_maps_.id(); }
  GLuint rawSampler() const { return raw_.id(); }
  GLuint compareSampler() const { return compare_.id(); }
  GLuint sunBlock() const { return sun_block_.id(); }

 private:
  // What a cube was rendered from: the light's shape and place, and the casters.
  struct CubeKey {
    std::array<float, 9> light{};  // position, radius, axis, length, far
    uint64_t casters = 0;          // hash of the object transforms and alpha masks
    int size = 0;
    bool operator==(const CubeKey&) const = default;
  };
  void writeShadowSlots(const Input& in, const ShadowAssignment& a);
  void ensureAtlas(int size, size_t cubes);
  void ensureSunMaps(int size, size_t layers);
  void renderCube(const PassContext& ctx, const Input& in, gl::PassBindings& b, size_t cube,
                  const Light& light, float far);
  // Renders directional light map `layer` from the orthographic view `view_proj`.
  void renderSun(const PassContext& ctx, const Input& in, gl::PassBindings& b, size_t layer,
                 const glm::mat4& view_proj);
  gl::Texture atlas_, sun_maps_;
  gl::Buffer sun_block_;  // GpuSunShadow[kMaxDirectionalLights]
  size_t sun_layers_ = 0;
  int sun_size_ = 0;
  // What a sun layer was rendered from: the light's direction and the map's frame, the casters.
  struct SunKey {
    std::array<float, 16> frame{};
    uint64_t casters = 0;
    int size = 0;
    bool operator==(const SunKey&) const = default;
  };
  std::vector<SunKey> suns_;
  gl::Framebuffer fbo_;
  gl::Sampler raw_, compare_;
  int size_ = 0;
  size_t layers_ = 0;                   // cubes the atlas has room for
  std::vector<CubeKey> cubes_;          // per cube: what it holds (size 0: nothing)
  std::vector<uint32_t> written_cube_;  // per light: the shadow_cube last written
  const GpuScene* written_for_ = nullptr;
  size_t written_version_ = 0;
  std::string warned_;  // the last over-budget warning, not repeated every frame
};

}  // namespace hv::render

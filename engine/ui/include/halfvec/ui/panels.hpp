// Window-free models behind the viewer's ImGui panels (material, lights, rendering settings,
// stats), plus the ImGui drawing functions that use them. The models only edit an hv::Scene and
// record what changed; the caller re-uploads (Renderer::updateMaterials / updateLights /
// setScene). Tests drive the models without a window or an ImGui context.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::ui {

// ---------------------------------------------------------------------------------------------
// Materials

class MaterialPanelModel {
 public:
  MaterialPanelModel() = default;
  // Edits `scene` in place; what it holds now becomes the "loaded" state that reset() restores.
  explicit MaterialPanelModel(Scene& scene) { attach(scene); }
  void attach(Scene& scene);

  size_t count() const { return scene_ ? scene_->materials.size() : 0; }
  int selected() const { return selected_; }
  void select(int index);  // clamped to the valid range
  const Material& current() const;
  const Material& loaded(int index) const { return loaded_.at(size_t(index)); }

  // Each setter clamps to the range the scene format accepts (base color, metallic, roughness,
  // cavity, alpha in [0, 1]; emissive in [0, kMaxEmissive]; shading model unlit or default_lit)
  // and returns true when the material changed.
  static constexpr float kMaxEmissive = 1000.0f;
  bool setBaseColor(glm::vec3 c);
  bool setMetallic(float v);
  bool setRoughness(float v);
  bool setCavity(float v);
  bool setEmissive(glm::vec3 e);
  bool setShadingModel(ShadingModel m);
  // The clear coat's weight and roughness (0..1; weight 0: default_lit, above: clear_coat).
  bool setClearCoat(float weight, float roughness);
  bool setAlpha(float v);  // the base colour's alpha: coverage when blended, tested when masked
  bool setAlphaMode(AlphaMode m);

  bool reset();     // the selected material back to its loaded value
  bool resetAll();  // every material
  bool modified(int index) const;

  // True once after any change: the caller calls Renderer::updateMaterials().
  bool takeDirty() {
    const bool d = dirty_;
    dirty_ = false;
    return d;
  }

  // Writes the edited materials back into the scene file at `path` (hv::saveSceneEdits: only the
  // changed fields of the changed materials, every other byte of the file kept). Returns the
  // number of materials changed; throws on I/O or JSON errors (SceneError, OutputError).
  int saveMaterials(const std::string& path) const;

 private:
  Material* mut();
  bool apply(const Material& before);
  Scene* scene_ = nullptr;
  std::vector<Material> loaded_;
  int selected_ = 0;
  bool dirty_ = false;
};

// ---------------------------------------------------------------------------------------------
// Lights

struct LightGenerator {
  int count = 64;
  float point_weight = 1.0f, sphere_weight = 1.0f, tube_weight = 1.0f;  // type mix
  glm::vec3 box_min{-5.0f, 0.2f, -5.0f}, box_max{5.0f, 3.0f, 5.0f};
  float intensity_min = 1.0f, intensity_max = 10.0f;
  float range = 3.0f;
  float radius = 0.1f;  // sphere / tube
  float length = 0.5f;  // tube
  uint32_t seed = 1;
};

// `gen.count` lights inside the box; the same parameters give the same lights.
std::vector<Light> generateLights(const LightGenerator& gen);

class LightsPanelModel {
 public:
  LightsPanelModel() = default;
  explicit LightsPanelModel(Scene& scene) { attach(scene); }
  void attach(Scene& scene);

  size_t count() const { return scene_ ? scene_->lights.size() : 0; }
  int selected() const { return selected_; }
  void select(int index);
  const Light* current() const;
  const std::vector<Light>& lights() const { return scene_->lights; }

  int add(LightType type);  // at the camera target; returns its index (selected)
  bool remove(int index);
  void clear();
  // Appends (or replaces all lights with) generateLights(gen).
  void generate(const LightGenerator& gen, bool replace);

  // Setters clamp: intensity, radius, length >= 0; range > 0; axis normalized (non-zero).
  bool setType(LightType t);
  bool setPosition(glm::vec3 p);
  bool setColor(glm::vec3 c);
  bool setIntensity(float v);
  bool setRadius(float v);
  bool setLength(float v);
  bool setAxis(glm::vec3 a);
  bool setDirection(glm::vec3 d);
  bool setConeAngles(glm::vec2 inner_outer);  // radians
  bool setAngularDiameter(float v);           // radians, in [0, kMaxAngularDiameter]
  bool setRange(float v);
  bool setShadows(bool on);  // the light casts shadows (a shadow map)
  // The scene's settings.shadow_filter (the filter of every shadowed light).
  ShadowFilter shadowFilter() const {
    return scene_ ? scene_->settings.shadow_filter : ShadowFilter::Pcss;
  }
  bool setShadowFilter(ShadowFilter f);

  bool takeDirty() {
    const bool d = dirty_;
    dirty_ = false;
    return d;
  }
  LightGenerator generator;  // the panel's generator settings

 private:
  Light* mut();
  Scene* scene_ = nullptr;
  int selected_ = -1;
  bool dirty_ = false;
};

// ---------------------------------------------------------------------------------------------
// Rendering settings

class RenderSettingsModel {
 public:
  struct EnumField {
    const char* label;
    std::span<const std::string_view> names;
    std::function<int(const RenderSettings&)> get;
    std::function<void(RenderSettings&, int)> set;
    bool needs_set_scene;  // environment bake depends on it (irradiance cube)
  };
  struct BoolField {
    const char* label;
    bool RenderSettings::*member;
  };
  struct FloatField {  // a slider over the row's [lo, hi] (settings.max_error)
    const char* label;
    float RenderSettings::*member;
    float lo, hi;
  };

  RenderSettingsModel();
  explicit RenderSettingsModel(Scene& scene) : RenderSettingsModel() { attach(scene); }
  void attach(Scene& scene) { scene_ = &scene; }

  const std::vector<EnumField>& enumFields() const { return enums_; }
  const std::vector<BoolField>& boolFields() const { return bools_; }
  const std::vector<FloatField>& floatFields() const { return floats_; }
  const RenderSettings& settings() const { return scene_->settings; }

  // Index into enumFields() / boolFields(); return true on change.
  bool setEnum(size_t field, int value);
  bool setBool(size_t field, bool value);
  bool setFloat(size_t field, float value);  // clamped to the field's range; NaN changes nothing
  bool setExposure(float v);                 // clamped to [1/64, 64]
  bool setEnvironmentIntensity(float v);
  bool setEnvironmentRotation(float deg);
  // Environment choice: none, uniform (with setEnvironmentColor), sky, or an HDR file. Each
  // change needs a rebake (takeNeedsSetScene). setEnvironmentHdr switches to that file; it
  // returns false, changing nothing, when the file does not exist (a file that exists but fails
  // to load throws from Renderer::setScene: the viewer restores the previous environment).
  bool setEnvironmentKind(EnvironmentKind k);
  bool setEnvironmentColor(glm::vec3 c);  // clamped to [0, 1000]
  bool setEnvironmentHdr(const std::string& path);
  const Environment& environment() const { return scene_->environment; }
  // HDR files offered by the panel (the viewer lists the shared assets' env folder).
  std::vector<std::string> hdr_choices;

  render::DebugView view = render::DebugView::None;
  static std::span<const char* const> debugViewNames();

  // True once after a change that needs Renderer::setScene (environment rebake).
  bool takeNeedsSetScene() {
    const bool d = needs_set_scene_;
    needs_set_scene_ = false;
    return d;
  }

 private:
  Scene* scene_ = nullptr;
  std::vector<EnumField> enums_;
  std::vector<BoolField> bools_;
  std::vector<FloatField> floats_;
  bool needs_set_scene_ = false;
};

// ---------------------------------------------------------------------------------------------
// Stats

class StatsModel {
 public:
  static constexpr size_t kHistory = 240;
  void push(const render::FrameStats& stats, double cpu_frame_ms);
  const render::FrameStats& last() const { return last_; }
  const std::vector<float>& frameTimes() const { return frame_ms_; }  // oldest first
  const std::vector<float>& gpuTimes() const { return gpu_ms_; }
  double averageFrameMs() const;
  double averageGpuMs() const;

 private:
  render::FrameStats last_;
  std::vector<float> frame_ms_, gpu_ms_;
};

// ---------------------------------------------------------------------------------------------
// ImGui drawing of the models: the contents of the side bar's tabs (sidebar.hpp; needs a current
// ImGui context, frame and window). Widgets leave room for their labels at any window width.
// Each returns true when the scene changed.

// `save_requested` is set when "Save scene" is pressed.
bool drawMaterialContents(MaterialPanelModel& model, bool* save_requested);
bool drawLightsContents(LightsPanelModel& model);
// With view options: the post-AA and emitter toggles too (they change no scene field).
bool drawRenderingContents(RenderSettingsModel& model, render::ViewOptions* view_options);
// With a manifest: a "Programs" section listing the last frame's programs, their keys, why each
// define is on and their compile times (docs/variants.md).
// `lights_in_view`: render::countLightsInView of the frame.
void drawStatsContents(const StatsModel& stats, size_t light_count, size_t lights_in_view,
                       const std::string& gpu_name, const render::Manifest* manifest = nullptr);
// A red error box; nothing when `message` is empty.
void drawErrorPanel(const std::string& title, const std::string& message);

}  // namespace hv::ui

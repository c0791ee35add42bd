// The panel models: plain C++ over hv::Scene, no ImGui, no GL.
#include "halfvec/ui/panels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <type_traits>

#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/light_generator.hpp"
#include "halfvec/scene/scene_writer.hpp"

namespace hv::ui {

namespace {

glm::vec3 clamp01(glm::vec3 v) {
  return glm::clamp(v, glm::vec3(0.0f), glm::vec3(1.0f));
}
float clamp01(float v) {
  return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
}
glm::vec3 finiteOr(glm::vec3 v, glm::vec3 fallback) {
  return (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) ? v : fallback;
}

bool sameMaterial(const Material& a, const Material& b) {
  return a.base_color == b.base_color && a.metallic == b.metallic && a.roughness == b.roughness &&
         a.cavity == b.cavity && a.emissive == b.emissive && a.model == b.model &&
         a.base_alpha == b.base_alpha && a.alpha_mode == b.alpha_mode;
}

bool sameLight(const Light& a, const Light& b) {
  return a.type == b.type && a.position == b.position && a.color == b.color &&
         a.intensity == b.intensity && a.radius == b.radius && a.length == b.length &&
         a.axis == b.axis && a.range == b.range && a.shadows == b.shadows;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

void MaterialPanelModel::attach(Scene& scene) {
  scene_ = &scene;
  loaded_ = scene.materials;
  selected_ = std::clamp(selected_, 0, std::max(0, int(loaded_.size()) - 1));
  dirty_ = false;
}

void MaterialPanelModel::select(int index) {
  selected_ = std::clamp(index, 0, std::max(0, int(count()) - 1));
}

const Material& MaterialPanelModel::current() const {
  if (!scene_ || scene_->materials.empty()) throw std::out_of_range("no materials");
  return scene_->materials[size_t(selected_)];
}

Material* MaterialPanelModel::mut() {
  if (!scene_ || scene_->materials.empty()) return nullptr;
  return &scene_->materials[size_t(selected_)];
}

bool MaterialPanelModel::apply(const Material& before) {
  const bool changed = !sameMaterial(before, current());
  dirty_ = dirty_ || changed;
  return changed;
}

bool MaterialPanelModel::setBaseColor(glm::vec3 c) {
  Material* m = mut();
  if (!m) return false;
  const Material before = *m;
  m->base_color = clamp01(finiteOr(c, before.base_color));
  return apply(before);
}

bool MaterialPanelModel::setMetallic(float v) {
  Material* m = mut();
  if (!m) return false;
  const Material before = *m;
  m->metallic = clamp01(v);
  return apply(before);
}

bool MaterialPanelModel::setRoughness(float v) {
  Material* m = mut();
  if (!m) return false;
  const Material before = *m;
  m->roughness = clamp01(v);
  return apply(before);
}

bool MaterialPanelModel::setCavity(float v) {
  Material* m = mut();
  if (!m) return false;
  const Material before = *m;
  m->cavity = clamp01(v);
  return apply(before);
}

bool MaterialPanelModel::setEmissive(glm::vec3 e) {
  Material* m = mut();
  if (!m) return false;
  const Material before = *m;
  m->emissive = glm::clamp(finiteOr(e, before.emissive), glm::vec3(0.0f), glm::vec3(kMaxEmissive));
  return apply(before);
}

bool MaterialPanelModel::setShadingModel(ShadingModel model) {
  Material* m = mut();
  if (!m || model == ShadingModel::Background) return false;  // background is not a material
  const Material before = *m;
  m->model = model;
  // clear_coat is the model of a coat above 0 (the scene loader's rule): a full coat when chosen
  // without one; no coat once another model is chosen.
  if (model == ShadingModel::ClearCoat && m->clearcoat == 0.0f) m->clearcoat = 1.0f;
  if (model != ShadingModel::ClearCoat) m->clearcoat = 0.0f;
  return apply(before);
}

bool MaterialPanelModel::setClearCoat(float weight, float roughness) {
  Material* m = mut();
  if (!m || m->model == ShadingModel::Unlit) return false;
  const Material before = *m;
  m->clearcoat = clamp01(weight);
  m->clearcoat_roughness = clamp01(roughness);
  m->model = m->clearcoat > 0.0f ? ShadingModel::ClearCoat : ShadingModel::DefaultLit;
  return apply(before);
}

bool MaterialPanelModel::setAlpha(float v) {
  Material* m = mut();
  if (!m) return false;
  const Material before = *m;
  m->base_alpha = clamp01(v);
  return apply(before);
}

bool MaterialPanelModel::setAlphaMode(AlphaMode mode) {
  Material* m = mut();
  if (!m) return false;
  const Material before = *m;
  m->alpha_mode = mode;
  return apply(before);
}

bool MaterialPanelModel::reset() {
  Material* m = mut();
  if (!m || size_t(selected_) >= loaded_.size()) return false;
  const Material before = *m;
  *m = loaded_[size_t(selected_)];
  return apply(before);
}

bool MaterialPanelModel::resetAll() {
  if (!scene_) return false;
  bool changed = false;
  for (size_t i = 0; i < scene_->materials.size() && i < loaded_.size(); ++i) {
    if (!sameMaterial(scene_->materials[i], loaded_[i])) {
      scene_->materials[i] = loaded_[i];
      changed = true;
    }
  }
  dirty_ = dirty_ || changed;
  return changed;
}

bool MaterialPanelModel::modified(int index) const {
  if (!scene_ || index < 0 || size_t(index) >= loaded_.size() ||
      size_t(index) >= scene_->materials.size()) {
    return false;
  }
  return !sameMaterial(scene_->materials[size_t(index)], loaded_[size_t(index)]);
}

int MaterialPanelModel::saveMaterials(const std::string& path) const {
  if (!scene_) throw std::runtime_error("no scene");
  // Two scenes that differ only in their materials: the writer then edits only those.
  Scene before, after;
  before.materials = loaded_;
  after.materials = scene_->materials;
  before.materials.resize(std::min(before.materials.size(), after.materials.size()));
  after.materials.resize(before.materials.size());
  int changed = 0;
  for (size_t i = 0; i < after.materials.size(); ++i) {
    changed += !after.materials[i].source.empty() &&
               !sameMaterial(before.materials[i], after.materials[i]);
  }
  saveSceneEdits(path, before, after);
  return changed;
}

// ---------------------------------------------------------------------------------------------

// The scene files' generator (halfvec/scene/light_generator.hpp) with the panel's single radius,
// length and range, and its saturation.
std::vector<Light> generateLights(const LightGenerator& gen) {
  std::vector<Light> out;
  if (gen.count <= 0) return out;
  LightGeneratorParams p;
  p.count = gen.count;
  p.seed = gen.seed;
  p.weights = glm::max(glm::vec3(gen.point_weight, gen.sphere_weight, gen.tube_weight), 0.0f);
  if (p.weights.x + p.weights.y + p.weights.z <= 0.0f) p.weights = {1.0f, 0.0f, 0.0f};
  p.volume_min = glm::min(gen.box_min, gen.box_max);
  p.volume_max = glm::max(gen.box_min, gen.box_max);
  const float imin = std::max(gen.intensity_min, 0.0f);
  p.intensity = {imin, std::max(gen.intensity_max, imin)};
  p.range = glm::vec2(std::max(gen.range, 0.01f));
  p.radius = glm::vec2(std::max(gen.radius, 0.0f));
  p.length = glm::vec2(std::max(gen.length, 0.0f));
  p.saturation = 0.6f;
  out.reserve(size_t(gen.count));
  hv::generateLights(p, out);
  return out;
}

void LightsPanelModel::attach(Scene& scene) {
  scene_ = &scene;
  selected_ = scene.lights.empty() ? -1 : std::clamp(selected_, 0, int(scene.lights.size()) - 1);
  dirty_ = false;
}

void LightsPanelModel::select(int index) {
  selected_ = count() == 0 ? -1 : std::clamp(index, 0, int(count()) - 1);
}

const Light* LightsPanelModel::current() const {
  if (!scene_ || selected_ < 0 || size_t(selected_) >= scene_->lights.size()) return nullptr;
  return &scene_->lights[size_t(selected_)];
}

Light* LightsPanelModel::mut() {
  return const_cast<Light*>(current());
}

int LightsPanelModel::add(LightType type) {
  if (!scene_) return -1;
  Light l;
  l.type = type;
  l.position = scene_->camera.target + glm::vec3(0.0f, 1.0f, 0.0f);
  if (type != LightType::Point && type != LightType::Spot) l.radius = 0.1f;
  if (type == LightType::Tube) l.length = 1.0f;
  scene_->lights.push_back(l);
  selected_ = int(scene_->lights.size()) - 1;
  dirty_ = true;
  return selected_;
}

bool LightsPanelModel::remove(int index) {
  if (!scene_ || index < 0 || size_t(index) >= scene_->lights.size()) return false;
  scene_->lights.erase(scene_->lights.begin() + index);
  select(selected_ > index ? selected_ - 1 : selected_);
  dirty_ = true;
  return true;
}

void LightsPanelModel::clear() {
  if (!scene_) return;
  scene_->lights.clear();
  selected_ = -1;
  dirty_ = true;
}

void LightsPanelModel::generate(const LightGenerator& gen, bool replace) {
  if (!scene_) return;
  if (replace) scene_->lights.clear();
  auto lights = generateLights(gen);
  scene_->lights.insert(scene_->lights.end(), lights.begin(), lights.end());
  select(selected_ < 0 ? 0 : selected_);
  dirty_ = true;
}

#define HV_LIGHT_SETTER(NAME, ARG, EXPR)    \
  bool LightsPanelModel::NAME(ARG) {        \
    Light* l = mut();                       \
    if (!l) return false;                   \
    const Light before = *l;                \
    EXPR;                                   \
    const bool ch = !sameLight(before, *l); \
    dirty_ = dirty_ || ch;                  \
    return ch;                              \
  }

HV_LIGHT_SETTER(setType, LightType t, l->type = t)
HV_LIGHT_SETTER(setPosition, glm::vec3 p, l->position = finiteOr(p, before.position))
HV_LIGHT_SETTER(setColor, glm::vec3 c, l->color = glm::max(finiteOr(c, before.color), glm::vec3(0)))
HV_LIGHT_SETTER(setIntensity, float v, l->intensity = std::isfinite(v) ? std::max(v, 0.0f) : 0.0f)
HV_LIGHT_SETTER(setRadius, float v, l->radius = std::isfinite(v) ? std::max(v, 0.0f) : 0.0f)
HV_LIGHT_SETTER(setLength, float v, l->length = std::isfinite(v) ? std::max(v, 0.0f) : 0.0f)
HV_LIGHT_SETTER(setAxis, glm::vec3 a,
                l->axis = glm::length(finiteOr(a, glm::vec3(0))) > 1e-6f ? glm::normalize(a)
                                                                         : before.axis)
HV_LIGHT_SETTER(setDirection, glm::vec3 d,
                l->direction = glm::length(finiteOr(d, glm::vec3(0))) > 1e-6f ? glm::normalize(d)
                                                                              : before.direction)
// The cone keeps 0 <= inner < outer <= pi/2, as a scene file must (scene_elements.cpp).
HV_LIGHT_SETTER(setConeAngles, glm::vec2 a,
                l->outer_cone_angle = std::isfinite(a.y) ? std::clamp(a.y, 1e-3f, 1.5707963f)
                                                         : before.outer_cone_angle;
                l->inner_cone_angle = std::isfinite(a.x)
                                          ? std::clamp(a.x, 0.0f, 0.999f * l->outer_cone_angle)
                                          : std::min(before.inner_cone_angle,
                                                     0.999f * l->outer_cone_angle))
HV_LIGHT_SETTER(setAngularDiameter, float v,
                l->angular_diameter = std::isfinite(v) ? std::clamp(v, 0.0f, kMaxAngularDiameter)
                                                       : before.angular_diameter)
HV_LIGHT_SETTER(setRange, float v, l->range = std::isfinite(v) ? std::max(v, 0.01f) : before.range)
HV_LIGHT_SETTER(setShadows, bool on, l->shadows = on)
#undef HV_LIGHT_SETTER

bool LightsPanelModel::setShadowFilter(ShadowFilter f) {
  if (!scene_ || scene_->settings.shadow_filter == f) return false;
  scene_->settings.shadow_filter = f;
  dirty_ = true;
  return true;
}

// ---------------------------------------------------------------------------------------------

// The controls are the settings table's rows that have a label (render_settings.hpp), in its order.
RenderSettingsModel::RenderSettingsModel() {
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if (!row.info.label) return;
    const auto member = row.member;
    if constexpr (std::is_same_v<T, bool>) {
      bools_.push_back({row.info.label, member});
    } else if constexpr (std::is_same_v<T, float>) {
      floats_.push_back({row.info.label, member, float(row.info.lo), float(row.info.hi)});
    } else if constexpr (std::is_enum_v<T>) {
      enums_.push_back({row.info.label, enumNames<T>(),
                        [member](const RenderSettings& s) { return int(s.*member); },
                        [member](RenderSettings& s, int v) { s.*member = T(v); },
                        row.info.needs_set_scene});
    }
  });
}

bool RenderSettingsModel::setEnum(size_t field, int value) {
  if (!scene_ || field >= enums_.size()) return false;
  const auto& f = enums_[field];
  if (value < 0 || size_t(value) >= f.names.size() || f.get(scene_->settings) == value) {
    return false;
  }
  f.set(scene_->settings, value);
  needs_set_scene_ = needs_set_scene_ || f.needs_set_scene;
  return true;
}

bool RenderSettingsModel::setBool(size_t field, bool value) {
  if (!scene_ || field >= bools_.size()) return false;
  bool& b = scene_->settings.*(bools_[field].member);
  if (b == value) return false;
  b = value;
  return true;
}

bool RenderSettingsModel::setFloat(size_t field, float value) {
  if (!scene_ || field >= floats_.size() || !std::isfinite(value)) return false;
  const FloatField& f = floats_[field];
  float& v = scene_->settings.*(f.member);
  value = std::clamp(value, f.lo, f.hi);
  if (v == value) return false;
  v = value;
  return true;
}

bool RenderSettingsModel::setExposure(float v) {
  if (!scene_ || !std::isfinite(v)) return false;
  v = std::clamp(v, 1.0f / 64.0f, 64.0f);
  if (scene_->settings.exposure == v) return false;
  scene_->settings.exposure = v;
  return true;
}

bool RenderSettingsModel::setEnvironmentIntensity(float v) {
  if (!scene_ || !std::isfinite(v)) return false;
  v = std::clamp(v, 0.0f, 1000.0f);
  if (scene_->environment.intensity == v) return false;
  scene_->environment.intensity = v;
  needs_set_scene_ = true;
  return true;
}

bool RenderSettingsModel::setEnvironmentRotation(float deg) {
  if (!scene_ || !std::isfinite(deg)) return false;
  deg = std::fmod(deg, 360.0f);
  if (scene_->environment.rotation_deg == deg) return false;
  scene_->environment.rotation_deg = deg;
  needs_set_scene_ = true;
  return true;
}

bool RenderSettingsModel::setEnvironmentKind(EnvironmentKind k) {
  if (!scene_ || scene_->environment.kind == k) return false;
  if (k == EnvironmentKind::HdrFile && scene_->environment.path.empty()) return false;
  scene_->environment.kind = k;
  needs_set_scene_ = true;
  return true;
}

bool RenderSettingsModel::setEnvironmentColor(glm::vec3 c) {
  if (!scene_) return false;
  for (int i = 0; i < 3; ++i) c[i] = std::isfinite(c[i]) ? std::clamp(c[i], 0.0f, 1000.0f) : 0.0f;
  if (scene_->environment.color == c) return false;
  scene_->environment.color = c;
  needs_set_scene_ = needs_set_scene_ || scene_->environment.kind == EnvironmentKind::Uniform;
  return true;
}

bool RenderSettingsModel::setEnvironmentHdr(const std::string& path) {
  if (!scene_ || path.empty()) return false;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  Environment& e = scene_->environment;
  if (e.kind == EnvironmentKind::HdrFile && e.path == path) return false;
  e.kind = EnvironmentKind::HdrFile;
  e.path = path;
  needs_set_scene_ = true;
  return true;
}

std::span<const char* const> RenderSettingsModel::debugViewNames() {
  static const std::array<const char*, render::kDebugViewCount> names = [] {
    std::array<const char*, render::kDebugViewCount> n{};
    for (size_t i = 0; i < n.size(); ++i) n[i] = render::toString(render::DebugView(i));
    return n;
  }();
  return names;
}

// ---------------------------------------------------------------------------------------------

void StatsModel::push(const render::FrameStats& stats, double cpu_frame_ms) {
  last_ = stats;
  if (frame_ms_.size() >= kHistory) frame_ms_.erase(frame_ms_.begin());
  if (gpu_ms_.size() >= kHistory) gpu_ms_.erase(gpu_ms_.begin());
  frame_ms_.push_back(float(cpu_frame_ms));
  gpu_ms_.push_back(float(stats.total_ms));
}

double StatsModel::averageFrameMs() const {
  if (frame_ms_.empty()) return 0.0;
  double s = 0;
  for (float v : frame_ms_) s += v;
  return s / double(frame_ms_.size());
}

double StatsModel::averageGpuMs() const {
  if (gpu_ms_.empty()) return 0.0;
  double s = 0;
  for (float v : gpu_ms_) s += v;
  return s / double(gpu_ms_.size());
}

}  // namespace hv::ui

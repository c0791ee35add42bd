// ImGui drawing of the panel models (no backend here: imgui.h only).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>

#include "imgui.h"
#include "halfvec/scene/enums.hpp"
#include "halfvec/ui/panels.hpp"

namespace hv::ui {

namespace {

// Widgets sized so that the widest of `labels` fits to their right: nothing is clipped at any
// side bar width (the layout test checks it). Pops with ImGui::PopItemWidth().
void pushLabelColumn(std::initializer_list<const char*> labels) {
  float w = 0.0f;
  for (const char* l : labels) w = std::max(w, ImGui::CalcTextSize(l, nullptr, true).x);
  ImGui::PushItemWidth(-(w + ImGui::GetStyle().ItemInnerSpacing.x + 1.0f));
}

// Combo over a list of names; returns true when the user picked another entry.
bool nameCombo(const char* label, int* current, std::span<const std::string_view> names) {
  bool changed = false;
  const std::string preview(*current >= 0 && size_t(*current) < names.size()
                                ? names[size_t(*current)]
                                : std::string_view("?"));
  if (ImGui::BeginCombo(label, preview.c_str())) {
    for (size_t i = 0; i < names.size(); ++i) {
      const std::string n(names[i]);
      const bool sel = int(i) == *current;
      if (ImGui::Selectable(n.c_str(), sel)) {
        changed = int(i) != *current;
        *current = int(i);
      }
      if (sel) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace

bool drawMaterialContents(MaterialPanelModel& model, bool* save_requested) {
  bool changed = false;
  if (model.count() == 0) {
    ImGui::TextUnformatted("no materials");
    return false;
  }
  pushLabelColumn({"material", "base color", "metallic", "roughness", "cavity", "emissive",
                   "shading model", "alpha mode", "alpha"});
  const Material& cur = model.current();
  std::string preview = cur.name.empty() ? "(unnamed)" : cur.name;
  if (ImGui::BeginCombo("material", preview.c_str())) {
    for (size_t i = 0; i < model.count(); ++i) {
      const Material& m = model.loaded(int(i));
      std::string label = (m.name.empty() ? std::string("(unnamed)") : m.name) +
                          (model.modified(int(i)) ? " *" : "") + "##" + std::to_string(i);
      if (ImGui::Selectable(label.c_str(), int(i) == model.selected())) model.select(int(i));
    }
    ImGui::EndCombo();
  }
  Material m = model.current();
  if (ImGui::ColorEdit3("base color", &m.base_color.x, ImGuiColorEditFlags_Float)) {
    changed |= model.setBaseColor(m.base_color);
  }
  if (ImGui::SliderFloat("metallic", &m.metallic, 0.0f, 1.0f))
    changed |= model.setMetallic(m.metallic);
  if (ImGui::SliderFloat("roughness", &m.roughness, 0.0f, 1.0f)) {
    changed |= model.setRoughness(m.roughness);
  }
  if (ImGui::SliderFloat("cavity", &m.cavity, 0.0f, 1.0f)) changed |= model.setCavity(m.cavity);
  if (ImGui::DragFloat3("emissive", &m.emissive.x, 0.05f, 0.0f, MaterialPanelModel::kMaxEmissive)) {
    changed |= model.setEmissive(m.emissive);
  }
  // Background (0) is not a material's shading model: offer unlit / default_lit.
  const auto names = enumNames<ShadingModel>().subspan(1);
  int model_index = int(m.model) - 1;
  if (nameCombo("shading model", &model_index, names)) {
    changed |= model.setShadingModel(ShadingModel(model_index + 1));
  }
  if (m.model != ShadingModel::Unlit) {
    const bool coat = ImGui::SliderFloat("coat", &m.clearcoat, 0.0f, 1.0f);
    if (ImGui::SliderFloat("coat rough", &m.clearcoat_roughness, 0.0f, 1.0f) || coat) {
      changed |= model.setClearCoat(m.clearcoat, m.clearcoat_roughness);
    }
  }
  int alpha_mode = int(m.alpha_mode);
  if (nameCombo("alpha mode", &alpha_mode, enumNames<AlphaMode>())) {
    changed |= model.setAlphaMode(AlphaMode(alpha_mode));
  }
  if (ImGui::SliderFloat("alpha", &m.base_alpha, 0.0f, 1.0f))
    changed |= model.setAlpha(m.base_alpha);
  ImGui::PopItemWidth();
  if (ImGui::Button("Reset")) changed |= model.reset();
  ImGui::SameLine();
  if (ImGui::Button("Reset all")) changed |= model.resetAll();
  ImGui::SameLine();
  if (ImGui::Button("Save scene") && save_requested) *save_requested = true;
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Write the edited materials, lights, environment and settings into the "
        "scene file, changing only what changed");
  }
  return changed;
}

namespace {
// The lights as a scrolling table (clipped: only the visible rows are drawn, so thousands of
// lights cost nothing); a click selects the light for editing below.
void drawLightTable(LightsPanelModel& model) {
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_SizingFixedFit;
  const float height = ImGui::GetTextLineHeightWithSpacing() * 7.5f;
  if (!ImGui::BeginTable("lights", 7, flags, ImVec2(0.0f, height))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* h : {"#", "type", "color", "intensity", "radius", "length", "position"}) {
    ImGui::TableSetupColumn(h);
  }
  ImGui::TableHeadersRow();
  const auto& lights = model.lights();
  ImGuiListClipper clipper;
  clipper.Begin(int(lights.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const Light& l = lights[size_t(i)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const std::string label = std::to_string(i);
      if (ImGui::Selectable(label.c_str(), i == model.selected(),
                            ImGuiSelectableFlags_SpanAllColumns)) {
        model.select(i);
      }
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(toString(l.type).data());
      ImGui::TableNextColumn();
      ImGui::ColorButton("##c", ImVec4(l.color.x, l.color.y, l.color.z, 1.0f),
                         ImGuiColorEditFlags_NoTooltip);
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", l.intensity);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", l.radius);
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", l.length);
      ImGui::TableNextColumn();
      ImGui::Text("%.2f %.2f %.2f", l.position.x, l.position.y, l.position.z);
    }
  }
  ImGui::EndTable();
}

// The selected light's shape and emission, each field edited through the model.
bool drawLightFields(LightsPanelModel& model, const Light& cur) {
  bool changed = false;
  Light l = cur;
  int type = int(l.type);
  if (nameCombo("type", &type, enumNames<LightType>())) changed |= model.setType(LightType(type));
  const bool directional = l.type == LightType::Directional;
  if (!directional && ImGui::DragFloat3("position", &l.position.x, 0.02f)) {
    changed |= model.setPosition(l.position);
  }
  if (ImGui::ColorEdit3("color", &l.color.x, ImGuiColorEditFlags_Float)) {
    changed |= model.setColor(l.color);
  }
  if (ImGui::DragFloat("intensity", &l.intensity, 0.1f, 0.0f, 1e4f)) {
    changed |= model.setIntensity(l.intensity);
  }
  if (directional) {  // no position, range or radius: a direction and the disk's size
    if (ImGui::DragFloat3("direction", &l.direction.x, 0.01f, -1.0f, 1.0f)) {
      changed |= model.setDirection(l.direction);
    }
    if (ImGui::DragFloat("angle (rad)", &l.angular_diameter, 0.0005f, 0.0f, kMaxAngularDiameter)) {
      changed |= model.setAngularDiameter(l.angular_diameter);
    }
    return changed;
  }
  if (ImGui::DragFloat("range", &l.range, 0.05f, 0.01f, 1e3f)) changed |= model.setRange(l.range);
  if (l.type != LightType::Point && ImGui::DragFloat("radius", &l.radius, 0.005f, 0.0f, 100.0f)) {
    changed |= model.setRadius(l.radius);
  }
  if (l.type == LightType::Tube) {
    if (ImGui::DragFloat("length", &l.length, 0.01f, 0.0f, 100.0f)) {
      changed |= model.setLength(l.length);
    }
    if (ImGui::DragFloat3("axis", &l.axis.x, 0.01f, -1.0f, 1.0f)) changed |= model.setAxis(l.axis);
  }
  if (l.type == LightType::Spot) {
    if (ImGui::DragFloat3("direction", &l.direction.x, 0.01f, -1.0f, 1.0f)) {
      changed |= model.setDirection(l.direction);
    }
    glm::vec2 cone(l.inner_cone_angle, l.outer_cone_angle);
    if (ImGui::DragFloat2("cone (rad)", &cone.x, 0.005f, 0.0f, 1.5707963f)) {
      changed |= model.setConeAngles(cone);
    }
  }
  return changed;
}

// Random lights replacing or appended to the scene's (halfvec/scene/light_generator.hpp).
bool drawLightGenerator(LightsPanelModel& model) {
  bool changed = false;
  if (ImGui::CollapsingHeader("Generate random lights")) {
    LightGenerator& g = model.generator;
    ImGui::SliderInt("count", &g.count, 1, 4096);
    ImGui::SliderFloat("point", &g.point_weight, 0.0f, 1.0f);
    ImGui::SliderFloat("sphere", &g.sphere_weight, 0.0f, 1.0f);
    ImGui::SliderFloat("tube", &g.tube_weight, 0.0f, 1.0f);
    ImGui::DragFloat3("box min", &g.box_min.x, 0.05f);
    ImGui::DragFloat3("box max", &g.box_max.x, 0.05f);
    ImGui::DragFloatRange2("intensity", &g.intensity_min, &g.intensity_max, 0.1f, 0.0f, 1e4f);
    ImGui::DragFloat("range##gen", &g.range, 0.05f, 0.01f, 100.0f);
    ImGui::DragFloat("radius##gen", &g.radius, 0.005f, 0.0f, 10.0f);
    ImGui::DragFloat("length##gen", &g.length, 0.01f, 0.0f, 10.0f);
    int seed = int(g.seed);
    if (ImGui::InputInt("seed", &seed)) g.seed = uint32_t(seed);
    if (ImGui::Button("Replace")) {
      model.generate(g, true);
      changed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Append")) {
      model.generate(g, false);
      changed = true;
    }
  }
  return changed;
}
}  // namespace

bool drawLightsContents(LightsPanelModel& model) {
  bool changed = false;
  ImGui::Text("%zu lights", model.count());
  int button = 0;
  for (LightType t : {LightType::Point, LightType::Sphere, LightType::Tube, LightType::Spot,
                      LightType::Directional}) {
    const std::string label = "+ " + std::string(toString(t));
    // Two rows (three, then two): five on one would overflow the panel at 960 x 540.
    if (button % 3 != 0) ImGui::SameLine();
    ++button;
    if (ImGui::SmallButton(label.c_str())) {
      model.add(t);
      changed = true;
    }
  }
  pushLabelColumn({"type",        "position", "color",         "intensity", "range",
                   "radius",      "length",   "axis",          "direction", "cone (rad)",
                   "angle (rad)", "shadows",  "shadow filter", "count",     "point",
                   "sphere",      "tube",     "box min",       "box max",   "seed"});
  if (model.count() > 0) {
    drawLightTable(model);
    if (const Light* cur = model.current()) {
      changed |= drawLightFields(model, *cur);
      bool shadows = cur->shadows;
      if (ImGui::Checkbox("shadows", &shadows)) changed |= model.setShadows(shadows);
      if (ImGui::Button("Remove")) changed |= model.remove(model.selected());
      ImGui::SameLine();
    }
    if (ImGui::Button("Remove all")) {
      model.clear();
      changed = true;
    }
    // One filter for every shadowed light (settings.shadow_filter; docs/lights.md "Shadows").
    int filter = int(model.shadowFilter());
    if (nameCombo("shadow filter", &filter, enumNames<ShadowFilter>())) {
      changed |= model.setShadowFilter(ShadowFilter(filter));
    }
  }
  changed |= drawLightGenerator(model);
  ImGui::PopItemWidth();
  return changed;
}

bool drawRenderingContents(RenderSettingsModel& model, render::ViewOptions* view_options) {
  bool changed = false;
  if (view_options) {
    bool aa = view_options->aa == render::PostAA::Fxaa;
    if (ImGui::Checkbox("anti-aliasing (FXAA)", &aa)) {
      view_options->aa = aa ? render::PostAA::Fxaa : render::PostAA::None;
    }
    ImGui::Checkbox("show sphere and tube lights", &view_options->emitters);
  }
  float label_w = ImGui::CalcTextSize("rotation (deg)").x;
  for (const auto& f : model.enumFields())
    label_w = std::max(label_w, ImGui::CalcTextSize(f.label).x);
  for (const auto& f : model.floatFields())
    label_w = std::max(label_w, ImGui::CalcTextSize(f.label).x);
  ImGui::PushItemWidth(-(label_w + ImGui::GetStyle().ItemInnerSpacing.x + 1.0f));
  const auto& enums = model.enumFields();
  for (size_t i = 0; i < enums.size(); ++i) {
    int v = enums[i].get(model.settings());
    if (nameCombo(enums[i].label, &v, enums[i].names)) changed |= model.setEnum(i, v);
  }
  const auto& bools = model.boolFields();
  for (size_t i = 0; i < bools.size(); ++i) {
    bool b = model.settings().*(bools[i].member);
    if (ImGui::Checkbox(bools[i].label, &b)) changed |= model.setBool(i, b);
  }
  const auto& floats = model.floatFields();
  for (size_t i = 0; i < floats.size(); ++i) {
    float v = model.settings().*(floats[i].member);
    if (ImGui::SliderFloat(floats[i].label, &v, floats[i].lo, floats[i].hi, "%.3f")) {
      changed |= model.setFloat(i, v);
    }
  }
  float exposure = model.settings().exposure;
  if (ImGui::SliderFloat("exposure", &exposure, 1.0f / 64.0f, 64.0f, "%.3f",
                         ImGuiSliderFlags_Logarithmic)) {
    changed |= model.setExposure(exposure);
  }
  if (ImGui::CollapsingHeader("Environment", ImGuiTreeNodeFlags_DefaultOpen)) {
    const Environment& env = model.environment();
    int kind = int(env.kind);
    if (nameCombo("environment", &kind, enumNames<EnvironmentKind>())) {
      changed |= model.setEnvironmentKind(EnvironmentKind(kind));
    }
    if (env.kind == EnvironmentKind::Uniform) {
      glm::vec3 c = env.color;
      if (ImGui::ColorEdit3("radiance", &c.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR))
        changed |= model.setEnvironmentColor(c);
    }
    if (!model.hdr_choices.empty()) {
      const std::string current = std::filesystem::path(env.path).filename().string();
      if (ImGui::BeginCombo("HDR file", current.empty() ? "(none)" : current.c_str())) {
        for (const std::string& f : model.hdr_choices) {
          const std::string name = std::filesystem::path(f).filename().string();
          if (ImGui::Selectable(name.c_str(), f == env.path)) changed |= model.setEnvironmentHdr(f);
        }
        ImGui::EndCombo();
      }
    }
    // Intensity and rotation rebake the environment: applied on Enter or the step buttons, not
    // on every step of a drag.
    float intensity = env.intensity;
    if (ImGui::InputFloat("intensity##env", &intensity, 0.1f, 1.0f, "%.2f",
                          ImGuiInputTextFlags_EnterReturnsTrue)) {
      changed |= model.setEnvironmentIntensity(intensity);
    }
    float rotation = env.rotation_deg;
    if (ImGui::InputFloat("rotation (deg)", &rotation, 15.0f, 90.0f, "%.1f",
                          ImGuiInputTextFlags_EnterReturnsTrue)) {
      changed |= model.setEnvironmentRotation(rotation);
    }
  }
  const auto views = RenderSettingsModel::debugViewNames();
  int view = int(model.view);
  if (ImGui::Combo("debug view", &view, views.data(), int(views.size()))) {
    model.view = render::DebugView(view);
    changed = true;
  }
  ImGui::PopItemWidth();
  return changed;
}

void drawStatsContents(const StatsModel& stats, size_t light_count, size_t lights_in_view,
                       const std::string& gpu_name, const render::Manifest* manifest) {
  const auto& last = stats.last();
  if (!gpu_name.empty()) ImGui::TextWrapped("%s", gpu_name.c_str());
  const int gbuffer_bytes =
      manifest ? manifest->gbuffer_bytes_per_pixel : render::kGBufferBytesPerPixel;
  const double gbuffer_mib = double(last.width) * last.height * gbuffer_bytes / (1024.0 * 1024.0);
  ImGui::TextWrapped("%dx%d, G-buffer %d B/px = %.2f MiB", last.width, last.height, gbuffer_bytes,
                     gbuffer_mib);
  const size_t tiles = size_t((last.width + render::kTileSize - 1) / render::kTileSize) *
                       size_t((last.height + render::kTileHeight - 1) / render::kTileHeight);
  ImGui::Text("lights %zu, in view %zu", light_count, lights_in_view);
  if (tiles > 0 && last.tile_light_entries > 0) {
    ImGui::TextWrapped("tile lists: %zu entries, %.1f lights/tile", last.tile_light_entries,
                       double(last.tile_light_entries) / double(tiles));
  }
  ImGui::TextWrapped("frame %.2f ms (%.1f fps), GPU %.3f ms", stats.averageFrameMs(),
                     stats.averageFrameMs() > 0 ? 1000.0 / stats.averageFrameMs() : 0.0,
                     stats.averageGpuMs());
  // Frame-time graph: explicit 0..1.25*max scale (auto-scaling with a flat history collapses the
  // range to nothing), label above the plot rather than an overlay.
  const auto& ft = stats.frameTimes();
  if (ft.size() >= 2) {
    const float top = *std::max_element(ft.begin(), ft.end());
    ImGui::TextWrapped("frame ms, last %zu frames (max %.1f)", ft.size(), double(top));
    ImGui::PlotLines("##frame", ft.data(), int(ft.size()), 0, nullptr, 0.0f,
                     std::max(top * 1.25f, 1e-3f), ImVec2(ImGui::GetContentRegionAvail().x, 60));
  }
  if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    for (const auto& [name, ms] : last.passes) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%8.3f ms", ms);
    }
    ImGui::EndTable();
  }
  if (manifest && ImGui::CollapsingHeader("Programs (variant manifest)")) {
    ImGui::TextWrapped("key: %s", manifest->key.c_str());
    ImGui::TextWrapped("binary cache: %s (%zu hits, %zu misses)", manifest->binary_cache.c_str(),
                       manifest->binary_hits, manifest->binary_misses);
    int id = 0;
    for (const auto& p : manifest->programs) {
      ImGui::PushID(id++);
      const double ms = p.from_binary_cache ? p.cache_load_ms : p.compile_ms + p.link_ms;
      if (ImGui::TreeNode("program", "%s  %.1f ms%s", p.name.c_str(), ms,
                          p.from_binary_cache ? " (binary cache)" : "")) {
        if (!p.from_binary_cache)
          ImGui::Text("compile %.1f ms, link %.1f ms", p.compile_ms, p.link_ms);
        for (const auto& r : p.reasons) {
          ImGui::Bullet();
          ImGui::TextWrapped("%s", r.c_str());
        }
        ImGui::TreePop();
      }
      ImGui::PopID();
    }
  }
}

void drawErrorPanel(const std::string& title, const std::string& message) {
  if (message.empty()) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 10), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(size.x * 0.6f, 0), ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.35f, 0.05f, 0.05f, 0.95f));
  ImGui::Begin(title.c_str(), nullptr, ImGuiWindowFlags_NoCollapse);
  ImGui::TextWrapped("%s", message.c_str());
  ImGui::End();
  ImGui::PopStyleColor();
}

}  // namespace hv::ui

// The viewer's UI: one side bar docked to the right edge of the window, its panels (Material,
// Lights, Render, Stats) as tabs, collapsible from its title bar and hidden with H. Its width is
// kSidebarWidth points times the window's content scale, so at 1280x720 it covers 300 / 1280 =
// 23% of the window; every widget leaves room for its label (nothing is clipped at 960x540, the
// layout test checks it).
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "halfvec/render/renderer.hpp"
#include "halfvec/ui/panels.hpp"

namespace hv::ui {

inline constexpr float kSidebarWidth = 300.0f;  // points at content scale 1

struct SidebarRect {
  float x = 0, y = 0, width = 0, height = 0;
};
// Where the side bar goes in a display of `display` pixels at content scale `scale`: the right
// edge, full height, kSidebarWidth * scale wide (at most the whole display).
SidebarRect sidebarRect(glm::vec2 display, float scale);

struct ViewerUi;
// The part of the framebuffer the scene is rendered into: left of the side bar while it is shown
// (the 3D view stays free: the side bar never covers the scene), the whole framebuffer when it
// is hidden. `window` is the window's size in window coordinates (the side bar's units).
glm::ivec2 sceneViewSize(const ViewerUi& ui, glm::ivec2 window, glm::ivec2 framebuffer);

// Everything the UI edits or shows.
struct ViewerUi {
  MaterialPanelModel materials;
  LightsPanelModel lights;
  RenderSettingsModel settings;
  StatsModel stats;
  render::ViewOptions view{render::PostAA::Fxaa, true, -1};  // on by default in the viewer
  bool visible = true;                                       // H
  float scale = 1.0f;                                        // content scale
  std::string status;                                        // last pick, save, drop
  std::string scene_error, shader_error;
  void attach(Scene& scene) {
    materials.attach(scene);
    lights.attach(scene);
    settings.attach(scene);
  }
};

// What the frame shows beside the models.
struct SidebarInfo {
  std::string gpu;
  size_t light_count = 0, lights_in_view = 0;
  const render::Manifest* manifest = nullptr;
};

struct SidebarActions {
  bool materials_changed = false, lights_changed = false, save = false;
};

// Draws the side bar (nothing when !ui.visible) and the error boxes. `tab` >= 0 selects that tab
// (0 Material, 1 Lights, 2 Render, 3 Stats) this frame, as a click on it would.
SidebarActions drawSidebar(ViewerUi& ui, const SidebarInfo& info, int tab = -1);

// Pixels by which the widest item of the last drawSidebar passed the side bar's inner right edge
// (0: nothing clipped). For the layout test.
float sidebarOverflow();

// Content scale for ImGui: fonts and style sizes scaled by `scale` (call between frames).
void applyContentScale(float scale);

}  // namespace hv::ui

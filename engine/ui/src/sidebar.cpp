// The side bar (sidebar.hpp).
#include "halfvec/ui/sidebar.hpp"

#include <algorithm>
#include <cmath>

#include "imgui.h"
#include "imgui_internal.h"  // the window's content extent, for the overflow check

namespace hv::ui {

namespace {
float g_overflow = 0.0f;

// How far the items drawn so far in the current window passed its inner right edge.
void noteOverflow() {
  const ImGuiWindow* w = ImGui::GetCurrentWindow();
  g_overflow = std::max(g_overflow, w->DC.CursorMaxPos.x - w->WorkRect.Max.x);
}
}  // namespace

SidebarRect sidebarRect(glm::vec2 display, float scale) {
  SidebarRect r;
  r.width = std::min(kSidebarWidth * std::max(scale, 0.5f), display.x);
  r.height = display.y;
  r.x = display.x - r.width;
  r.y = 0.0f;
  return r;
}

glm::ivec2 sceneViewSize(const ViewerUi& ui, glm::ivec2 window, glm::ivec2 framebuffer) {
  if (!ui.visible || window.x <= 0) return framebuffer;
  const SidebarRect r = sidebarRect(glm::vec2(window), ui.scale);
  const int bar = int(std::ceil(r.width * float(framebuffer.x) / float(window.x)));
  return {std::max(framebuffer.x - bar, 1), framebuffer.y};
}

SidebarActions drawSidebar(ViewerUi& ui, const SidebarInfo& info, int tab) {
  SidebarActions act;
  g_overflow = 0.0f;
  drawErrorPanel("Scene error (showing the last good scene)", ui.scene_error);
  drawErrorPanel("Shader error (last good programs still running; fix and press R)",
                 ui.shader_error);
  if (!ui.visible) return act;
  const ImVec2 d = ImGui::GetIO().DisplaySize;
  const SidebarRect r = sidebarRect({d.x, d.y}, ui.scale);
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.width, r.height), ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize;
  if (!ImGui::Begin("halfvec (H hides the UI, F frames)", nullptr, flags)) {
    ImGui::End();
    return act;
  }
  if (!ui.status.empty()) ImGui::TextWrapped("%s", ui.status.c_str());
  const char* names[] = {"Material", "Lights", "Render", "Stats"};
  if (ImGui::BeginTabBar("panels")) {
    for (int i = 0; i < 4; ++i) {
      const ImGuiTabItemFlags f = i == tab ? ImGuiTabItemFlags_SetSelected : 0;
      if (!ImGui::BeginTabItem(names[i], nullptr, f)) continue;
      switch (i) {
        case 0:
          act.materials_changed = drawMaterialContents(ui.materials, &act.save);
          break;
        case 1:
          act.lights_changed = drawLightsContents(ui.lights);
          break;
        case 2:
          drawRenderingContents(ui.settings, &ui.view);
          break;
        default:
          drawStatsContents(ui.stats, info.light_count, info.lights_in_view, info.gpu,
                            info.manifest);
      }
      noteOverflow();
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  noteOverflow();
  ImGui::End();
  return act;
}

float sidebarOverflow() {
  return std::max(g_overflow, 0.0f);
}

void applyContentScale(float scale) {
  scale = std::clamp(scale, 0.5f, 4.0f);
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  ImGui::GetIO().FontGlobalScale = scale;
}

}  // namespace hv::ui

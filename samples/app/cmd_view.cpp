// `halfvec view`: interactive viewer. The same Renderer as `render`, drawing into the window's
// default framebuffer, with the ImGui panels (engine/ui) on top.
#include "halfvec/gl/gl.hpp"  // before GLFW, which must not pull in GL/gl.h
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/commands.hpp"
#include "app/scene_reload.hpp"
#include "halfvec/gl/shader_source.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/pick.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/ui/imgui_layer.hpp"
#include "halfvec/ui/panels.hpp"

namespace hv::app {

namespace {
constexpr const char* kViewHelp = R"(Usage: halfvec view SCENE.json [options]

Opens SCENE.json in a window with material, lights, rendering and stats panels.

Options:
  --size WxH            window size (default 1280x720)
  --frames N            quit after N frames (for tests and timing)
  --screenshot FILE.png after the last frame, save the window (scene + panels)
  --click X,Y           scripted left click at window pixel X,Y on the first frame (as a
                        mouse click: picks the material there; for tests and screenshots)
  -h, --help            this text

Controls: left drag orbit, right/middle drag pan, wheel zoom (around the camera target),
left click (no drag) on an object: select its material in the Material panel,
WASD fly (Q/E down/up; Shift faster), F12 save out/view_<n>.png + .pfm, R reload shaders
(an error keeps the last good programs running and shows in a panel), Esc quit.
The scene file is reloaded when it changes on disk.
)";

struct ViewArgs {
  std::string scene, screenshot;
  SceneOpenOptions open;
  bool print_scene = false;
  int width = 1280, height = 720, frames = 0;
  std::optional<glm::dvec2> click;  // scripted click, window coordinates
};

ViewArgs parse(const Args& args) {
  ViewArgs r;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (takeSceneOption(args, i, r.open, r.print_scene)) {
      continue;
    } else if (a == "--size") {
      parseSize(value(), r.width, r.height);
    } else if (a == "--frames") {
      r.frames = std::atoi(value().c_str());
      if (r.frames < 1) throw UsageError{"--frames expects a positive count"};
    } else if (a == "--screenshot") {
      r.screenshot = value();
    } else if (a == "--click") {
      const std::string v = value();
      double x = 0, y = 0;
      char comma = 0;
      std::istringstream in(v);
      if (!(in >> x >> comma >> y) || comma != ',' || x < 0 || y < 0) {
        throw UsageError{"--click expects X,Y (window pixels), got '" + v + "'"};
      }
      r.click = glm::dvec2(x, y);
    } else {
      takeScenePath(a, r.scene);
    }
  }
  if (r.scene.empty()) throw UsageError{"no scene file given"};
  return r;
}

double g_scroll = 0.0;  // wheel steps since the last frame (GLFW callback -> main loop)

// The window's back buffer, row 0 = top.
ImageRGBA8 readFramebuffer(int w, int h) {
  ImageRGBA8 img;
  img.width = w;
  img.height = h;
  img.px.resize(size_t(w) * size_t(h) * 4);
  std::vector<uint8_t> rows(img.px.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  const size_t stride = size_t(w) * 4;
  for (int y = 0; y < h; ++y) {
    std::copy_n(rows.data() + size_t(h - 1 - y) * stride, stride,
                img.px.data() + size_t(y) * stride);
  }
  for (size_t i = 3; i < img.px.size(); i += 4) img.px[i] = 255;
  return img;
}

// Orbit / pan / zoom / fly around Camera::target.
struct CameraController {
  double last_x = 0, last_y = 0;
  bool dragging[3] = {false, false, false};

  void update(GLFWwindow* win, Camera& cam, bool ui_mouse, bool ui_keys, float dt) {
    double x, y;
    glfwGetCursorPos(win, &x, &y);
    const float dx = float(x - last_x), dy = float(y - last_y);
    last_x = x;
    last_y = y;
    glm::vec3 offset = cam.position - cam.target;
    float dist = glm::length(offset);
    if (dist < 1e-4f) dist = 1e-4f;
    const glm::vec3 fwd = -offset / dist;
    const glm::vec3 right = glm::normalize(glm::cross(fwd, cam.up));
    const glm::vec3 up = glm::cross(right, fwd);
    for (int b = 0; b < 3; ++b) {
      const bool down = glfwGetMouseButton(win, b) == GLFW_PRESS;
      if (!down)
        dragging[b] = false;
      else if (!dragging[b] && !ui_mouse)
        dragging[b] = true;  // drags start outside the panels
    }
    if (dragging[GLFW_MOUSE_BUTTON_LEFT] && (dx != 0 || dy != 0)) {
      // Yaw about the world up, pitch about the right axis, kept off the poles.
      const glm::vec3 wup = glm::normalize(cam.up);
      float yaw = -dx * 0.005f, pitch = -dy * 0.005f;
      const float elev = std::asin(glm::clamp(glm::dot(offset / dist, wup), -1.0f, 1.0f));
      pitch = glm::clamp(elev + pitch, -1.5f, 1.5f) - elev;
      glm::vec3 o = offset / dist;
      auto rot = [](glm::vec3 v, glm::vec3 axis, float a) {
        return v * std::cos(a) + glm::cross(axis, v) * std::sin(a) +
               axis * glm::dot(axis, v) * (1.0f - std::cos(a));
      };
      o = rot(o, right, pitch);
      o = rot(o, wup, yaw);
      cam.position = cam.target + o * dist;
    }
    const bool pan = dragging[GLFW_MOUSE_BUTTON_RIGHT] || dragging[GLFW_MOUSE_BUTTON_MIDDLE];
    if (pan && (dx != 0 || dy != 0)) {
      int wh = 1, ww = 1;
      glfwGetWindowSize(win, &ww, &wh);
      const float scale = 2.0f * dist * std::tan(glm::radians(cam.fov_y_deg) * 0.5f) / float(wh);
      const glm::vec3 move = (-dx * right + dy * up) * scale;
      cam.position += move;
      cam.target += move;
    }
    if (g_scroll != 0.0 && !ui_mouse) {
      const float nd = glm::clamp(dist * std::pow(0.9f, float(g_scroll)), 0.05f, 500.0f);
      cam.position = cam.target - fwd * nd;
    }
    g_scroll = 0.0;
    if (!ui_keys) {
      glm::vec3 v(0.0f);
      if (glfwGetKey(win, GLFW_KEY_W) == GLFW_PRESS) v += fwd;
      if (glfwGetKey(win, GLFW_KEY_S) == GLFW_PRESS) v -= fwd;
      if (glfwGetKey(win, GLFW_KEY_D) == GLFW_PRESS) v += right;
      if (glfwGetKey(win, GLFW_KEY_A) == GLFW_PRESS) v -= right;
      if (glfwGetKey(win, GLFW_KEY_E) == GLFW_PRESS) v += up;
      if (glfwGetKey(win, GLFW_KEY_Q) == GLFW_PRESS) v -= up;
      if (v != glm::vec3(0.0f)) {
        const float speed = std::max(dist, 1.0f) * 0.8f *
                            (glfwGetKey(win, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 4.0f : 1.0f);
        const glm::vec3 move = glm::normalize(v) * speed * dt;
        cam.position += move;
        cam.target += move;
      }
    }
  }
};

// A left click that is not a drag: pressed outside the panels and released within a few pixels
// of where it was pressed (a longer move is an orbit). Window coordinates.
struct ClickDetector {
  static constexpr double kSlop = 3.0;  // pixels of movement still counted as a click
  bool down = false, armed = false;
  glm::dvec2 start{0.0};

  std::optional<glm::dvec2> update(GLFWwindow* win, bool ui_mouse) {
    glm::dvec2 p;
    glfwGetCursorPos(win, &p.x, &p.y);
    const bool now = glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    std::optional<glm::dvec2> click;
    if (now && !down) {
      armed = !ui_mouse;
      start = p;
    } else if (now && glm::length(p - start) > kSlop) {
      armed = false;
    } else if (!now && down && armed) {
      click = p;
    }
    down = now;
    return click;
  }
};

// Selects the material of the object under window point `at` in the material panel; returns a
// status line for the panel. The pick is a CPU ray cast (render/pick.hpp).
std::string pickMaterial(GLFWwindow* win, const Scene& scene, glm::ivec2 fb, glm::dvec2 at,
                         ui::MaterialPanelModel& materials) {
  int ww = 1, wh = 1;
  glfwGetWindowSize(win, &ww, &wh);
  // Window coordinates -> framebuffer pixels (they differ on high-DPI displays).
  const glm::vec2 px(float(at.x * fb.x / std::max(ww, 1)), float(at.y * fb.y / std::max(wh, 1)));
  const auto hit = render::pick(scene, fb.x, fb.y, px);
  if (!hit) return "picked: background (no material)";
  materials.select(hit->material);
  const Material& m = scene.materials.at(size_t(hit->material));
  const Object& o = scene.objects.at(size_t(hit->object));
  return "picked material " + std::to_string(hit->material) + " '" + m.name + "' on object '" +
         o.name + "'";
}

// The HDR environments the rendering panel offers: *.hdr in ${HV_ASSETS_DIR}/env, sorted.
std::vector<std::string> hdrChoices() {
  std::vector<std::string> out;
  try {
    const std::filesystem::path dir =
        std::filesystem::path(expandEnvVars("${HV_ASSETS_DIR}")) / "env";
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
      if (e.path().extension() == ".hdr")
        out.push_back(std::filesystem::absolute(e.path()).string());
    }
  } catch (const std::exception&) {  // no assets: the panel offers none
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A key's press edge.
struct KeyEdge {
  int key;
  bool was = false;
  bool pressed(GLFWwindow* w) {
    const bool now = glfwGetKey(w, key) == GLFW_PRESS;
    const bool edge = now && !was;
    was = now;
    return edge;
  }
};

}  // namespace

int cmdView(const Args& args) {
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(kViewHelp, stdout);
      return 0;
    }
  }
  const ViewArgs va = parse(args);
  if (va.print_scene) return printScene(va.scene, va.open);
  // Load before opening a window: a bad scene file fails without one.
  SceneReloader reloader(va.scene, va.open);

  auto ctx = createWindowContext(va.width, va.height, "halfvec view - " + va.scene);
  GLFWwindow* win = ctx->window();
  glfwSetScrollCallback(win, [](GLFWwindow*, double, double y) { g_scroll += y; });
  if (va.frames > 0) glfwSwapInterval(0);  // scripted runs: no vsync wait
  render::Renderer renderer;
  reloader.attach(renderer);
  Scene* scene = &reloader.scene();
  ui::ImGuiLayer imgui(win);  // after our callbacks: the backend chains to them

  ui::MaterialPanelModel materials(*scene);
  ui::LightsPanelModel lights(*scene);
  ui::RenderSettingsModel settings(*scene);
  ui::StatsModel stats;
  settings.hdr_choices = hdrChoices();
  Environment good_environment = scene->environment;  // the last one that baked
  std::string panel_status;  // the material panel's status line: picks, saves
  std::string scene_error, shader_error;
  bool shaders_ok = true;
  CameraController controller;
  ClickDetector clicks;
  KeyEdge key_f12{GLFW_KEY_F12}, key_r{GLFW_KEY_R}, key_esc{GLFW_KEY_ESCAPE};
  const std::string gpu = ctx->renderer();
  int shot_index = 0;

  auto last = std::chrono::steady_clock::now();
  auto last_poll = last;
  int frame = 0;
  while (!ctx->shouldClose()) {
    ctx->pollEvents();
    const glm::ivec2 fb = ctx->framebufferSize();
    if (fb.x <= 0 || fb.y <= 0) {  // minimized: nothing to draw into
      glfwWaitEventsTimeout(0.1);
      last = std::chrono::steady_clock::now();
      continue;
    }
    const auto now = std::chrono::steady_clock::now();
    const double frame_ms = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;

    // Scene file changed on disk: reload, keep the last good scene on failure.
    if (now - last_poll > std::chrono::milliseconds(250)) {
      last_poll = now;
      if (reloader.poll()) {
        scene = &reloader.scene();
        materials.attach(*scene);
        lights.attach(*scene);
        settings.attach(*scene);
        good_environment = scene->environment;
      }
      scene_error = reloader.error();
    }

    imgui.beginFrame();
    // Before the camera moves: a click picks in the frame the user clicked on.
    std::optional<glm::dvec2> click = clicks.update(win, imgui.wantsMouse());
    if (frame == 0 && va.click) click = va.click;
    if (click) {
      panel_status = pickMaterial(win, *scene, fb, *click, materials);
      std::printf("%s\n", panel_status.c_str());
    }
    controller.update(win, scene->camera, imgui.wantsMouse(), imgui.wantsKeyboard(),
                      float(std::min(frame_ms, 100.0) / 1000.0));
    if (!imgui.wantsKeyboard()) {
      if (key_esc.pressed(win)) glfwSetWindowShouldClose(win, GLFW_TRUE);
      if (key_r.pressed(win)) {
        // Rebuild every program from the files as they are now; on an error the last good
        // programs keep rendering and the panel shows the error (file:line).
        try {
          renderer.programs().reloadAll();
          shaders_ok = true;
          shader_error.clear();
          std::printf("shaders reloaded\n");
        } catch (const std::exception& e) {
          shader_error = e.what();
          std::fprintf(stderr, "shader reload failed: %s\n", e.what());
        }
      }
    }

    if (ui::drawMaterialPanel(materials, va.scene, &panel_status)) renderer.updateMaterials();
    if (ui::drawLightsPanel(lights)) renderer.updateLights();
    ui::drawRenderingPanel(settings);
    if (settings.takeNeedsSetScene()) {
      try {
        renderer.setScene(*scene);
        good_environment = scene->environment;
      } catch (const std::exception& e) {
        // A bad HDR: back to the environment that worked, the error in the panel.
        scene_error = e.what();
        scene->environment = good_environment;
        try {
          renderer.setScene(*scene);
        } catch (const std::exception&) {
        }
      }
    }
    materials.takeDirty();
    lights.takeDirty();
    const render::Manifest manifest = renderer.manifest();
    ui::drawStatsPanel(stats, scene->lights.size(), render::countLightsInView(*scene, fb.x, fb.y),
                       gpu, &manifest);
    ui::drawErrorPanel("Scene error (showing the last good scene)", scene_error);
    ui::drawErrorPanel("Shader error (last good programs still running; fix and press R)",
                       shader_error);

    if (shaders_ok) {
      try {
        stats.push(renderer.render(fb.x, fb.y, settings.view, GLuint(0)), frame_ms);
      } catch (const gl::ShaderError& e) {
        shaders_ok = false;  // retried after the next R
        shader_error = e.what();
        std::fprintf(stderr, "shader error: %s\n", e.what());
      } catch (const std::exception& e) {
        shaders_ok = false;
        shader_error = e.what();
        std::fprintf(stderr, "render error: %s\n", e.what());
      }
    }
    if (!shaders_ok) {
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
      glViewport(0, 0, fb.x, fb.y);
      glDisable(GL_SCISSOR_TEST);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb.x, fb.y);
    imgui.endFrame();

    if (key_f12.pressed(win) && shaders_ok) {
      std::filesystem::create_directories("out");
      std::string base;
      do {
        base = "out/view_" + std::to_string(shot_index++);
      } while (std::filesystem::exists(base + ".png"));
      writePng(base + ".png", renderer.readLdr());
      writePfm(base + ".pfm", renderer.readHdr());
      panel_status = "saved " + base + ".png / .pfm";
      std::printf("%s\n", panel_status.c_str());
    }
    ++frame;
    const bool last_frame = va.frames > 0 && frame >= va.frames;
    if (last_frame && !va.screenshot.empty()) {
      const auto dir = std::filesystem::path(va.screenshot).parent_path();
      if (!dir.empty()) std::filesystem::create_directories(dir);
      writePng(va.screenshot, readFramebuffer(fb.x, fb.y));
      std::printf("screenshot: %s\n", std::filesystem::absolute(va.screenshot).string().c_str());
    }
    ctx->swapBuffers();
    if (last_frame) break;
  }
  if (!stats.frameTimes().empty()) {
    std::printf("frames: %d, mean frame %.2f ms, mean GPU %.3f ms (%s)\n", frame,
                stats.averageFrameMs(), stats.averageGpuMs(), gpu.c_str());
    for (const auto& [name, ms] : stats.last().passes)
      std::printf("  %-12s %8.3f ms\n", name.c_str(), ms);
  }
  return 0;
}

}  // namespace hv::app

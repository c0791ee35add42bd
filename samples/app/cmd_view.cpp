// `halfvec view`: interactive viewer. The same Renderer as `render`, drawing into the window's
// default framebuffer, with the side bar (engine/ui) on top. Input comes from GLFW event
// callbacks (ui::ViewerInput), so no key tap is lost at low frame rates.
#include "halfvec/gl/gl.hpp"  // before GLFW, which must not pull in GL/gl.h
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/scene_reload.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/pick.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene_writer.hpp"
#include "halfvec/ui/camera_control.hpp"
#include "halfvec/ui/imgui_layer.hpp"
#include "halfvec/ui/sidebar.hpp"
#include "halfvec/ui/viewer_input.hpp"
#include "halfvec/ui/viewer_window.hpp"

namespace hv::app {

namespace {
constexpr const char* kViewHelp = R"(Usage: halfvec view SCENE [options]

Opens SCENE, a scene file (.json) or a glTF model (.gltf, .glb; framed automatically), in a
window with the Material, Lights, Render and Stats panels in a side bar.

Options:
  --size WxH            window size (default 1280x720)
  --env FILE.hdr        replace the scene's environment with this HDR
  --camera N            a model's own camera N instead of the automatic framing
  --set PATH=VALUE      override a scene field (as render --set; repeatable)
  --print-scene         print the scene JSON (for a model: the one made for it; --set,
                        --look and the camera options applied) and exit
  --camera-position X,Y,Z  camera position (= --set camera.position=[X,Y,Z])
  --camera-target X,Y,Z    camera target (= --set camera.target=[X,Y,Z])
  --fov DEG             vertical field of view in degrees (= --set camera.fov_y_deg=DEG)
  --no-key-light        a model without the default key light (image-based lighting only)
  --look gltf|scene     gltf: the glTF viewers' conventions (no key light, PBR Neutral tone
                        map, sRGB output, no dither; --set applies after it); default scene
  --frames N            quit after N frames (for tests and timing)
  --screenshot FILE.png after the last frame, save the window (scene + side bar)
  --click X,Y           scripted left click at window pixel X,Y on the first frame (picks there)
  --press KEY           scripted tap of KEY (a letter, F12 or Esc) before the first frame,
                        through the same event queue as the keyboard (repeatable)
  --drop FILE           scripted drop of FILE on the window on the first frame (repeatable)
  -h, --help            this text

Mouse: left drag orbit, right/middle drag pan, wheel zoom (around the camera target); left click
(no drag) on an object: pick it (highlighted, its material in the Material panel).
Keys: WASD fly (Q/E down/up, Shift faster), F frame the picked object or the whole scene,
H hide/show the UI, F12 save out/view_<n>.png + .pfm, R reload the shaders (an error keeps the
last good programs running and shows in a panel), Esc quit.
Drop a .gltf/.glb/.json on the window to open it, an .hdr to light the scene with it.
The scene file is reloaded when it changes on disk; "Save scene" writes the edits into it.
Without a display, run it under a virtual X server: xvfb-run -a halfvec view SCENE ...
)";

struct ViewArgs {
  std::string scene, screenshot;
  SceneOpenOptions open;
  bool print_scene = false;
  int width = 1280, height = 720, frames = 0;
  std::optional<glm::dvec2> click;  // scripted click, window coordinates
  std::vector<int> presses;         // scripted key taps (GLFW key codes)
  std::vector<std::string> drops;   // scripted drops
};

ViewArgs parse(const Args& args) {
  ViewArgs r;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (takeSceneOption(args, i, r.open, r.print_scene)) continue;
    if (a == "--size") {
      parseSize(value(), r.width, r.height);
    } else if (a == "--frames") {
      r.frames = intInRange(a, value(), 1, 2147483647);
    } else if (a == "--screenshot") {
      r.screenshot = value();
    } else if (a == "--press") {
      const std::string k = value();
      if (ui::keyCode(k) < 0)
        throw UsageError{"--press expects a letter, F12 or Esc, got '" + k + "'"};
      r.presses.push_back(ui::keyCode(k));
    } else if (a == "--drop") {
      r.drops.push_back(value());
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

// The window, or an error that says how to get one.
std::unique_ptr<Context> openWindow(const ViewArgs& va) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  try {
    return createWindowContext(va.width, va.height, "halfvec view - " + va.scene);
  } catch (const ContextError& e) {
    if ((display && *display) || (wayland && *wayland)) throw;
    throw ContextError(std::string(e.what()) +
                       "\nno display (DISPLAY is not set): run the viewer under a virtual X "
                       "server, e.g.\n  xvfb-run -a -s '-screen 0 1920x1080x24' halfvec view " +
                       va.scene + " --frames 10 --screenshot out/view.png");
  }
}

class Viewer {
 public:
  Viewer(const ViewArgs& va, SceneReloader& reloader, Context& ctx)
      : va_(va), reloader_(&reloader), ctx_(ctx), win_(ctx.window()), input_(win_) {
    if (va.frames > 0) glfwSwapInterval(0);           // scripted runs: no vsync wait
    imgui_ = std::make_unique<ui::ImGuiLayer>(win_);  // after input_: its backend chains to ours
    ui_.scale = ui::windowContentScale(win_);
    ui::applyContentScale(ui_.scale);
    reloader.attach(renderer_);
    attachScene();
    ui_.settings.hdr_choices = ui::hdrChoices();
    gpu_ = ctx.renderer();
    for (int k : va.presses) input_.onKey(k, GLFW_PRESS), input_.onKey(k, GLFW_RELEASE);
  }
  int run();

 private:
  void attachScene();
  void handleKeys(const glm::ivec2& fb);
  void handleDrops();
  void openDropped(const std::string& path);
  void pickAt(glm::dvec2 at, glm::ivec2 fb);
  void applyPanels(const ui::SidebarActions& act);
  void renderFrame(glm::ivec2 view, glm::ivec2 fb, double frame_ms);
  void save();
  void saveShot();
  void printSummary(int frames) const;

  const ViewArgs& va_;
  SceneReloader* reloader_;
  std::unique_ptr<SceneReloader> owned_reloader_;  // a dropped scene
  Context& ctx_;
  GLFWwindow* win_;
  ui::ViewerInput input_;
  std::unique_ptr<ui::ImGuiLayer> imgui_;
  render::Renderer renderer_;
  Scene* scene_ = nullptr;
  Scene snapshot_;                // the scene as loaded (materials, lights, settings...)
  Environment good_environment_;  // the last environment that baked
  ui::ViewerUi ui_;
  ui::OrbitController controller_;
  ui::ClickDetector clicks_;
  std::string gpu_;
  bool shaders_ok_ = true, quit_ = false, shot_ = false;
  int shot_index_ = 0;
};

void Viewer::attachScene() {
  scene_ = &reloader_->scene();
  ui_.attach(*scene_);
  snapshot_ = ui::editableCopy(*scene_);
  good_environment_ = scene_->environment;
  ui_.view.highlight_object = -1;
}

void Viewer::handleKeys(const glm::ivec2& fb) {
  const bool typing = imgui_->wantsKeyboard();
  for (int key : input_.takePresses()) {
    if (typing) continue;  // the key went into a text field
    if (key == GLFW_KEY_ESCAPE) quit_ = true;
    if (key == GLFW_KEY_H) ui_.visible = !ui_.visible;
    if (key == GLFW_KEY_F12) shot_ = true;
    if (key == GLFW_KEY_F) {
      ui::frameView(*scene_, ui_.view.highlight_object, float(fb.x) / float(std::max(fb.y, 1)),
                    scene_->camera);
    }
    if (key == GLFW_KEY_R) {
      // Rebuild every program from the files as they are now; on an error the last good
      // programs keep rendering and the panel shows the error (file:line).
      try {
        renderer_.programs().reloadAll();
        shaders_ok_ = true;
        ui_.shader_error.clear();
        std::printf("shaders reloaded\n");
      } catch (const std::exception& e) {
        ui_.shader_error = e.what();
        std::fprintf(stderr, "shader reload failed: %s\n", e.what());
      }
    }
  }
}

void Viewer::openDropped(const std::string& path) {
  const ui::DropKind kind = ui::dropKind(path);
  if (kind == ui::DropKind::Environment) {
    const bool ok = ui_.settings.setEnvironmentHdr(std::filesystem::absolute(path).string());
    ui_.status = ok ? "environment: " + path : "cannot open " + path;
  } else if (kind == ui::DropKind::Scene) {
    try {
      auto fresh = std::make_unique<SceneReloader>(path);
      fresh->attach(renderer_);
      owned_reloader_ = std::move(fresh);
      reloader_ = owned_reloader_.get();
      attachScene();
      glfwSetWindowTitle(win_, ("halfvec view - " + path).c_str());
      ui_.status = "opened " + path;
      ui_.scene_error.clear();
    } catch (const std::exception& e) {
      renderer_.setScene(*scene_);  // back to the scene that was open
      ui_.scene_error = e.what();
      ui_.status = "cannot open " + path;
    }
  } else {
    ui_.status = "cannot open " + path + ": expected a .gltf, .glb, .json or .hdr file";
  }
  std::printf("%s\n", ui_.status.c_str());
}

void Viewer::handleDrops() {
  for (const std::string& p : input_.takeDrops()) openDropped(p);
}

// `fb`: the size of the scene view (left of the side bar).
void Viewer::pickAt(glm::dvec2 at, glm::ivec2 fb) {
  const glm::vec2 px = ui::windowToFramebuffer(win_, at, ctx_.framebufferSize());
  const auto hit = render::pick(*scene_, fb.x, fb.y, px);
  ui_.view.highlight_object = hit ? hit->object : -1;
  if (!hit) {
    ui_.status = "picked: background (no material)";
  } else {
    ui_.materials.select(hit->material);
    ui_.status = "picked material " + std::to_string(hit->material) + " '" +
                 scene_->materials.at(size_t(hit->material)).name + "' on object '" +
                 scene_->objects.at(size_t(hit->object)).name + "'";
  }
  std::printf("%s\n", ui_.status.c_str());
}

void Viewer::save() {
  if (isModelPath(reloader_->path())) {
    ui_.status = "a model has no scene file to save into: start one with halfvec view " +
                 reloader_->path() + " --print-scene > scene.json";
    return;
  }
  try {
    const size_t n = saveSceneEdits(reloader_->path(), snapshot_, *scene_);
    snapshot_ = ui::editableCopy(*scene_);
    ui_.status = "saved " + std::to_string(n) + " changes to " + reloader_->path();
  } catch (const std::exception& e) {
    ui_.status = std::string("save failed: ") + e.what();
  }
}

void Viewer::applyPanels(const ui::SidebarActions& act) {
  if (act.materials_changed) renderer_.updateMaterials();
  if (act.lights_changed) renderer_.updateLights();
  if (act.save) save();
  if (!ui_.settings.takeNeedsSetScene()) return;
  try {
    renderer_.setScene(*scene_);
    good_environment_ = scene_->environment;
  } catch (const std::exception& e) {
    // A bad HDR: back to the environment that worked, the error in the panel.
    ui_.scene_error = e.what();
    scene_->environment = good_environment_;
    renderer_.setScene(*scene_);
  }
}

// The scene into the `view` part of the window (left of the side bar), the UI over all of it.
void Viewer::renderFrame(glm::ivec2 view, glm::ivec2 fb, double frame_ms) {
  ui::clearWindow(fb, glm::vec3(0.08f, 0.08f, 0.1f));
  if (shaders_ok_) {
    try {
      renderer_.setViewOptions(ui_.view);
      ui_.stats.push(renderer_.render(view.x, view.y, ui_.settings.view, GLuint(0)), frame_ms);
    } catch (const std::exception& e) {  // a shader error included: retried after the next R
      shaders_ok_ = false;
      ui_.shader_error = e.what();
      std::fprintf(stderr, "render error: %s\n", e.what());
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb.x, fb.y);
  imgui_->endFrame();
}

void Viewer::saveShot() {
  shot_ = false;
  if (!shaders_ok_) return;
  std::filesystem::create_directories("out");
  std::string base;
  do {
    base = "out/view_" + std::to_string(shot_index_++);
  } while (std::filesystem::exists(base + ".png"));
  OutputFiles out;
  writePng(out.add(base + ".png").string(), renderer_.readLdr());
  writePfm(out.add(base + ".pfm").string(), renderer_.readHdr());
  out.commit();
  ui_.status = "saved " + base + ".png / .pfm";
  std::printf("%s\n", ui_.status.c_str());
}

int Viewer::run() {
  auto last = std::chrono::steady_clock::now(), last_poll = last;
  int frame = 0;
  while (!ctx_.shouldClose() && !quit_) {
    ctx_.pollEvents();
    const glm::ivec2 fb = ctx_.framebufferSize();
    const glm::ivec2 view = ui::sceneViewSize(ui_, ui::windowSize(win_), fb);
    if (fb.x <= 0 || fb.y <= 0) {  // minimized: nothing to draw into
      glfwWaitEventsTimeout(0.1);
      last = std::chrono::steady_clock::now();
      continue;
    }
    const auto now = std::chrono::steady_clock::now();
    const double frame_ms = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
    if (now - last_poll > std::chrono::milliseconds(250)) {  // the file changed on disk
      last_poll = now;
      if (reloader_->poll()) attachScene();
      ui_.scene_error = reloader_->error();
    }
    if (frame == 0) {
      for (const std::string& d : va_.drops) input_.onDrop({d});
    }
    handleDrops();
    if (const float s = input_.takeContentScale(); s > 0.0f) ui::applyContentScale(ui_.scale = s);
    imgui_->beginFrame();
    // Before the camera moves: a click picks in the frame the user clicked on.
    const ui::PointerState pointer = ui::readPointer(win_);
    std::optional<glm::dvec2> click = clicks_.update(pointer, imgui_->wantsMouse());
    if (frame == 0 && va_.click) click = va_.click;
    if (click) pickAt(*click, view);
    handleKeys(view);
    controller_.update(pointer, ui::windowSize(win_), input_.takeScroll(), ui::flyKeys(input_),
                       imgui_->wantsMouse(), imgui_->wantsKeyboard(),
                       float(std::min(frame_ms, 100.0) / 1000.0), scene_->camera);
    const render::Manifest manifest = renderer_.manifest();
    const ui::SidebarInfo info{gpu_, scene_->lights.size(),
                               render::countLightsInView(*scene_, view.x, view.y), &manifest};
    applyPanels(ui::drawSidebar(ui_, info));
    renderFrame(view, fb, frame_ms);
    if (shot_) saveShot();
    ++frame;
    const bool last_frame = va_.frames > 0 && frame >= va_.frames;
    if (last_frame && !va_.screenshot.empty()) {
      ui::writeWindowPng(va_.screenshot, fb);
      std::printf("screenshot: %s\n", std::filesystem::absolute(va_.screenshot).string().c_str());
    }
    ctx_.swapBuffers();
    if (last_frame) break;
  }
  printSummary(frame);
  return 0;
}

void Viewer::printSummary(int frames) const {
  if (ui_.stats.frameTimes().empty()) return;
  std::printf("frames: %d, mean frame %.2f ms, mean GPU %.3f ms (%s)\n", frames,
              ui_.stats.averageFrameMs(), ui_.stats.averageGpuMs(), gpu_.c_str());
  for (const auto& [name, ms] : ui_.stats.last().passes) {
    std::printf("  %-12s %8.3f ms\n", name.c_str(), ms);
  }
}

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
  SceneReloader reloader(va.scene, va.open);  // a bad scene file fails before a window opens
  auto ctx = openWindow(va);
  Viewer viewer(va, reloader, *ctx);
  return viewer.run();
}

}  // namespace hv::app

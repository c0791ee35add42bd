// The viewer staying out of the way: key taps from events (a press and its release inside one
// frame are not lost), the side bar's layout (coverage at 1280x720 measured from screenshots with
// and without the UI; nothing clipped at 960x540, checked in a headless ImGui frame), H, F, drops.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include <GLFW/glfw3.h>

#include "halfvec/image/image.hpp"
#include "halfvec/scene/model_scene.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/ui/camera_control.hpp"
#include "halfvec/ui/sidebar.hpp"
#include "halfvec/ui/viewer_input.hpp"
#include "halfvec/ui/viewer_window.hpp"
#include "imgui.h"
#include "ui/xvfb.hpp"

using hv::test::numbered;
using hv::test::ViewerWindow;

namespace {

std::string sample(const char* name) {
  return std::string(HV_SOURCE_DIR) + "/samples/scenes/" + name;
}

std::string tmpPath(const char* stem, const char* ext) {
  return (std::filesystem::temp_directory_path() / numbered(stem, int(getpid()), ext)).string();
}

// Runs a shell command, returns (exit status, output).
std::pair<int, std::string> run(const std::string& cmd) {
  const std::string log = tmpPath("hv_ux_log_", ".txt");
  const int rc = std::system((cmd + " > '" + log + "' 2>&1").c_str());
  std::ifstream in(log);
  std::string out((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(log);
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, out};
}

}  // namespace

TEST(ViewerInput, PressAndReleaseInOneFrameIsOneTap) {
  hv::ui::ViewerInput in;
  in.onKey(GLFW_KEY_F12, GLFW_PRESS);
  in.onKey(GLFW_KEY_F12, GLFW_RELEASE);  // both before the frame reads the input
  in.onKey(GLFW_KEY_H, GLFW_PRESS);
  in.onKey(GLFW_KEY_H, GLFW_REPEAT);  // auto-repeat is not a new tap
  EXPECT_FALSE(in.held(GLFW_KEY_F12));
  EXPECT_TRUE(in.held(GLFW_KEY_H));
  EXPECT_EQ(in.takePresses(), (std::vector<int>{GLFW_KEY_F12, GLFW_KEY_H}));
  EXPECT_TRUE(in.takePresses().empty());  // delivered once
  in.onScroll(1.0);
  in.onScroll(2.0);
  EXPECT_DOUBLE_EQ(in.takeScroll(), 3.0);
  EXPECT_DOUBLE_EQ(in.takeScroll(), 0.0);
  in.onContentScale(1.5f);  // moved to a denser monitor
  EXPECT_FLOAT_EQ(in.takeContentScale(), 1.5f);
  EXPECT_FLOAT_EQ(in.takeContentScale(), 0.0f);
  in.onDrop({"a.glb", "b.hdr"});
  EXPECT_EQ(in.takeDrops(), (std::vector<std::string>{"a.glb", "b.hdr"}));
}

TEST(ViewerDrop, FileKinds) {
  using hv::ui::DropKind;
  EXPECT_EQ(hv::ui::dropKind("/x/Helmet.GLB"), DropKind::Scene);
  EXPECT_EQ(hv::ui::dropKind("m.gltf"), DropKind::Scene);
  EXPECT_EQ(hv::ui::dropKind("scene.json"), DropKind::Scene);
  EXPECT_EQ(hv::ui::dropKind("sky.HDR"), DropKind::Environment);
  EXPECT_EQ(hv::ui::dropKind("notes.txt"), DropKind::Unsupported);
}

TEST(ViewerLayout, SidebarCoversAtMostAQuarterAt1280x720) {
  const hv::ui::SidebarRect r = hv::ui::sidebarRect({1280.0f, 720.0f}, 1.0f);
  const double covered = double(r.width) * r.height / (1280.0 * 720.0);
  EXPECT_LE(covered, 0.25);
  EXPECT_FLOAT_EQ(r.x + r.width, 1280.0f);  // docked right
  // Content scale 2 on a 2560x1440 framebuffer: the same share.
  const hv::ui::SidebarRect r2 = hv::ui::sidebarRect({2560.0f, 1440.0f}, 2.0f);
  EXPECT_LE(double(r2.width) * r2.height / (2560.0 * 1440.0), 0.25);
}

// Every tab drawn in a headless ImGui frame at 960x540 and 1280x720, content scale 1 and 1.5:
// no widget or label passes the side bar's inner right edge.
TEST(ViewerLayout, NothingClippedAt960x540) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  unsigned char* pixels = nullptr;
  int tw = 0, th = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &tw, &th);
  hv::Scene scene = hv::loadScene(sample("area_lights.json"));
  hv::ui::ViewerUi ui;
  ui.attach(scene);
  ui.lights.select(0);
  ui.settings.hdr_choices = {"/some/where/venice_sunset_1k.hdr"};
  hv::ui::SidebarInfo info{"llvmpipe (LLVM 15.0.6, 256 bits)", scene.lights.size(), 3, nullptr};
  for (float scale : {1.0f, 1.5f}) {
    hv::ui::applyContentScale(scale);
    ui.scale = scale;
    for (glm::vec2 d : {glm::vec2(960, 540), glm::vec2(1280, 720)}) {
      io.DisplaySize = ImVec2(d.x * scale, d.y * scale);
      for (int tab = 0; tab < 4; ++tab) {
        float overflow = 0.0f;
        for (int frame = 0; frame < 3; ++frame) {  // the tab switch lands on the next frame
          io.DeltaTime = 1.0f / 60.0f;
          ImGui::NewFrame();
          hv::ui::drawSidebar(ui, info, tab);
          overflow = hv::ui::sidebarOverflow();
          ImGui::Render();
        }
        EXPECT_LE(overflow, 0.0f) << "tab " << tab << " at " << d.x << "x" << d.y << " scale "
                                  << scale;
      }
    }
  }
  ImGui::DestroyContext();
}

TEST(ViewerCamera, FrameViewFitsTheObjectFromTheCurrentDirection) {
  hv::Scene s = hv::loadScene(sample("default.json"));
  hv::Camera cam = s.camera;
  const glm::vec3 dir_before = glm::normalize(cam.position - cam.target);
  int gold = -1;
  for (size_t i = 0; i < s.objects.size(); ++i) {
    if (s.objects[i].name == "gold_sphere") gold = int(i);
  }
  ASSERT_GE(gold, 0);
  hv::ui::frameView(s, gold, 16.0f / 9.0f, cam);
  // Looks at the sphere (center (-1.8, 0.5, 0), radius 0.5) from the same direction, close.
  EXPECT_LT(glm::length(cam.target - glm::vec3(-1.8f, 0.5f, 0.0f)), 0.1f);
  EXPECT_GT(glm::dot(glm::normalize(cam.position - cam.target), dir_before), 0.99f);
  EXPECT_LT(glm::length(cam.position - cam.target), 2.5f);
  EXPECT_LT(cam.near_plane, glm::length(cam.position - cam.target) - 0.5f);
}

TEST(ViewerCamera, ZoomAndFlyScaleWithTheDistance) {
  hv::Camera cam;
  cam.position = {0, 0, 0.01f};  // a millimeter-scale view
  cam.target = {0, 0, 0};
  cam.near_plane = 1e-4f;
  hv::ui::OrbitController c;
  hv::ui::PointerState p;
  c.update(p, {100, 100}, 5.0, {}, false, false, 0.0f, cam);  // five wheel steps in
  EXPECT_NEAR(glm::length(cam.position), 0.01f * std::pow(0.9f, 5.0f), 1e-6f);
  hv::ui::FlyKeys k;
  k.forward = true;
  const float d = glm::length(cam.position);
  c.update(p, {100, 100}, 0.0, k, false, false, 0.1f, cam);  // 0.1 s forward
  EXPECT_NEAR(glm::length(cam.target), 0.08f * d, 1e-6f);    // 0.8 distances per second
}

// Coverage measured from two screenshots with the UI, of the scene at two exposures: every pixel
// of the scene changes, the UI's stay (the pixels that stay are the UI's, plus whatever the tone
// map clips to white at both exposures: the emitters, a few hundred pixels).
TEST_F(ViewerWindow, SidebarCoversAtMostAQuarterOfA1280x720Window) {
  const std::string a_png = tmpPath("hv_ux_a_", ".png"), b_png = tmpPath("hv_ux_b_", ".png");
  const std::string base = "DISPLAY=" + server->display() + " '" + exe + "' view '" +
                           sample("default.json") + "' --size 1280x720 --frames 2 ";
  const auto ra = run(base + "--screenshot '" + a_png + "'");
  ASSERT_EQ(ra.first, 0) << ra.second;
  const auto rb = run(base + "--set settings.exposure=2 --screenshot '" + b_png + "'");
  ASSERT_EQ(rb.first, 0) << rb.second;
  const hv::ImageRGBA8 a = hv::readPng(a_png), b = hv::readPng(b_png);
  ASSERT_EQ(a.px.size(), b.px.size());
  size_t same = 0;
  for (size_t i = 0; i < a.px.size(); i += 4) {
    same += a.px[i] == b.px[i] && a.px[i + 1] == b.px[i + 1] && a.px[i + 2] == b.px[i + 2];
  }
  const double covered = double(same) / double(a.width * a.height);
  std::printf("UI covers %.1f%% of the 1280x720 window (pixels unchanged by the exposure)\n",
              100.0 * covered);
  EXPECT_GT(covered, 0.05);  // the UI is there
  EXPECT_LE(covered, 0.25);
  // H hides it: the scene then fills the window.
  ASSERT_EQ(run(base + "--press H --screenshot '" + a_png + "'").first, 0);
  ASSERT_EQ(run(base + "--press H --set settings.exposure=2 --screenshot '" + b_png + "'").first,
            0);
  const hv::ImageRGBA8 c = hv::readPng(a_png), d = hv::readPng(b_png);
  size_t same_hidden = 0;
  for (size_t i = 0; i < c.px.size(); i += 4)
    same_hidden += c.px[i] == d.px[i] && c.px[i + 1] == d.px[i + 1];
  std::printf("with H: %.2f%% unchanged\n",
              100.0 * double(same_hidden) / double(c.width * c.height));
  EXPECT_LT(double(same_hidden) / double(c.width * c.height), 0.02);
  std::filesystem::remove(a_png);
  std::filesystem::remove(b_png);
}

TEST_F(ViewerWindow, DroppedFilesOpen) {
  // A tiny valid Radiance file (flat scanlines: widths under 8 are never RLE).
  const std::string hdr = tmpPath("hv_ux_env_", ".hdr");
  {
    std::ofstream f(hdr, std::ios::binary);
    f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n";
    for (int i = 0; i < 32; ++i) f.write("\x80\x80\x80\x81", 4);
  }
  const std::string txt = tmpPath("hv_ux_notes_", ".txt");
  std::ofstream(txt) << "x";
  const auto [rc, out] = run("DISPLAY=" + server->display() + " '" + exe + "' view '" +
                             sample("default.json") + "' --size 320x180 --frames 3 --drop '" + hdr +
                             "' --drop '" + sample("sphere_grid.json") + "' --drop '" + txt + "'");
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("environment: " + hdr), std::string::npos) << out;
  EXPECT_NE(out.find("opened " + sample("sphere_grid.json")), std::string::npos) << out;
  EXPECT_NE(out.find("expected a .gltf, .glb, .json or .hdr"), std::string::npos) << out;
  std::filesystem::remove(hdr);
  std::filesystem::remove(txt);
}

TEST_F(ViewerWindow, OpensAModelByPath) {
  const std::filesystem::path model = std::filesystem::path(HV_ASSETS_DIR) / "gltf" /
                                      "DamagedHelmet" / "glTF-Binary" / "DamagedHelmet.glb";
  if (!std::filesystem::exists(model)) GTEST_SKIP() << "no shared assets at " << HV_ASSETS_DIR;
  const auto [rc, out] = run("DISPLAY=" + server->display() + " '" + exe + "' view '" +
                             model.string() + "' --size 320x180 --frames 2");
  EXPECT_EQ(rc, 0) << out;
}

TEST(Viewer, WithoutADisplaySaysToUseXvfbRun) {
  const std::string exe = std::string(HV_BINARY_DIR) + "/halfvec";
  if (access(exe.c_str(), X_OK) != 0) GTEST_SKIP() << exe << " not built";
  const auto [rc, out] =
      run("env -u DISPLAY -u WAYLAND_DISPLAY '" + exe + "' view '" + sample("default.json") + "'");
  EXPECT_EQ(rc, 1);
  EXPECT_NE(out.find("xvfb-run"), std::string::npos) << out;
}

#if HV_HAVE_XLIB
// A key tap whose press and release both arrive between two frames (sent back to back through
// the X server while the viewer renders at a few frames per second): Esc still quits.
TEST_F(ViewerWindow, TapInsideOneFrameIsNotLost) {
  const pid_t pid = fork();
  if (pid == 0) {
    setenv("DISPLAY", server->display().c_str(), 1);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execl(exe.c_str(), exe.c_str(), "view", sample("default.json").c_str(), "--size", "320x180",
          "--frames", "100000", static_cast<char*>(nullptr));
    _exit(127);
  }
  ASSERT_GT(pid, 0);
  Display* d = XOpenDisplay(server->display().c_str());
  ASSERT_NE(d, nullptr);
  Window win = 0;
  for (int i = 0; i < 600 && !win; ++i) {
    win = hv::test::findViewerWindow(d);
    if (!win) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  std::this_thread::sleep_for(std::chrono::seconds(2));  // rendering frames by now
  int status = -1;
  bool exited = false;
  if (win) {
    hv::test::sendKey(d, win, XK_Escape, true);
    for (int i = 0; i < 600 && !exited; ++i) {
      exited = waitpid(pid, &status, WNOHANG) == pid;
      if (!exited) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  XCloseDisplay(d);
  if (!exited) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  ASSERT_NE(win, Window(0)) << "the viewer's window never appeared";
  EXPECT_TRUE(exited) << "the Esc tap (press + release in one frame) was lost";
}
#endif

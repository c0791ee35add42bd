#include "halfvec/ui/viewer_window.hpp"

#include "halfvec/gl/gl.hpp"  // before GLFW, which must not pull in GL/gl.h
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "halfvec/core/output_files.hpp"
#include "halfvec/scene/model_scene.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::ui {

float windowContentScale(GLFWwindow* window) {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window, &x, &y);
  const float s = std::max(x, y);
  return s > 0.0f ? s : 1.0f;
}

glm::ivec2 windowSize(GLFWwindow* window) {
  glm::ivec2 s(1);
  glfwGetWindowSize(window, &s.x, &s.y);
  return s;
}

glm::vec2 windowToFramebuffer(GLFWwindow* window, glm::dvec2 at, glm::ivec2 fb) {
  const glm::ivec2 w = glm::max(windowSize(window), glm::ivec2(1));
  return {float(at.x * fb.x / w.x), float(at.y * fb.y / w.y)};
}

FlyKeys flyKeys(const ViewerInput& in) {
  FlyKeys k;
  k.forward = in.held(GLFW_KEY_W);
  k.back = in.held(GLFW_KEY_S);
  k.left = in.held(GLFW_KEY_A);
  k.right = in.held(GLFW_KEY_D);
  k.up = in.held(GLFW_KEY_E);
  k.down = in.held(GLFW_KEY_Q);
  k.fast = in.held(GLFW_KEY_LEFT_SHIFT) || in.held(GLFW_KEY_RIGHT_SHIFT);
  return k;
}

int keyCode(const std::string& name) {
  if (name == "F12") return GLFW_KEY_F12;
  if (name == "Esc" || name == "Escape") return GLFW_KEY_ESCAPE;
  if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0]))) {
    return GLFW_KEY_A + (std::toupper(static_cast<unsigned char>(name[0])) - 'A');
  }
  return -1;
}

DropKind dropKind(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".hdr") return DropKind::Environment;
  if (ext == ".json" || isModelPath(path)) return DropKind::Scene;
  return DropKind::Unsupported;
}

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

Scene editableCopy(const Scene& scene) {
  Scene s;
  s.source_path = scene.source_path;
  s.camera = scene.camera;
  s.materials = scene.materials;
  s.lights = scene.lights;
  s.environment = scene.environment;
  s.settings = scene.settings;
  return s;
}

ImageRGBA8 readWindow(glm::ivec2 fb) {
  ImageRGBA8 img = makeImageRGBA8(fb.x, fb.y);
  std::vector<uint8_t> rows(img.px.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, fb.x, fb.y, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  const size_t stride = size_t(fb.x) * 4;
  for (int y = 0; y < fb.y; ++y) {
    std::copy_n(rows.data() + size_t(fb.y - 1 - y) * stride, stride,
                img.px.data() + size_t(y) * stride);
  }
  for (size_t i = 3; i < img.px.size(); i += 4) img.px[i] = 255;
  return img;
}

void writeWindowPng(const std::string& path, glm::ivec2 fb) {
  const auto dir = std::filesystem::path(path).parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir);
  OutputFiles out;
  writePng(out.add(path).string(), readWindow(fb));
  out.commit();
}

void clearWindow(glm::ivec2 fb, glm::vec3 color) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glViewport(0, 0, fb.x, fb.y);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(color.x, color.y, color.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace hv::ui

#include "halfvec/ui/viewer_input.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace hv::ui {

namespace {
ViewerInput* self(GLFWwindow* w) {
  return static_cast<ViewerInput*>(glfwGetWindowUserPointer(w));
}
}  // namespace

ViewerInput::ViewerInput(GLFWwindow* window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (ViewerInput* in = self(w)) in->onKey(key, action);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    if (ViewerInput* in = self(w)) in->onScroll(dy);
  });
  glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
    if (ViewerInput* in = self(w)) in->onDrop(std::vector<std::string>(paths, paths + count));
  });
  glfwSetWindowContentScaleCallback(window, [](GLFWwindow* w, float x, float y) {
    if (ViewerInput* in = self(w)) in->onContentScale(std::max(x, y));
  });
}

void ViewerInput::onKey(int key, int action) {
  if (action == GLFW_PRESS) {
    presses_.push_back(key);
    held_.insert(key);
  } else if (action == GLFW_RELEASE) {
    held_.erase(key);
  }
}

void ViewerInput::onScroll(double dy) {
  scroll_ += dy;
}

void ViewerInput::onDrop(const std::vector<std::string>& paths) {
  drops_.insert(drops_.end(), paths.begin(), paths.end());
}

std::vector<int> ViewerInput::takePresses() {
  std::vector<int> out;
  out.swap(presses_);
  return out;
}

double ViewerInput::takeScroll() {
  const double s = scroll_;
  scroll_ = 0.0;
  return s;
}

std::vector<std::string> ViewerInput::takeDrops() {
  std::vector<std::string> out;
  out.swap(drops_);
  return out;
}

}  // namespace hv::ui

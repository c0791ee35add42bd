// The viewer's keyboard, wheel and drag-and-drop input from GLFW event callbacks, queued until the
// frame reads it. Polling key states once per frame loses a tap whose press and release both
// arrive between two frames (at 1-3 fps on a software rasterizer, most taps); events are never
// lost: a press is delivered to the next frame even when the key is already up again.
#pragma once

#include <set>
#include <string>
#include <vector>

struct GLFWwindow;

namespace hv::ui {

class ViewerInput {
 public:
  ViewerInput() = default;
  // Installs the key, scroll, drop and content-scale callbacks on `window` (call before ImGuiLayer,
  // whose GLFW backend chains to the callbacks already installed). The object must outlive the
  // window's use.
  explicit ViewerInput(GLFWwindow* window);
  ViewerInput(const ViewerInput&) = delete;
  ViewerInput& operator=(const ViewerInput&) = delete;

  // What the callbacks call (tests call them directly). `key` and `action` are GLFW's values.
  void onKey(int key, int action);
  void onScroll(double dy);
  void onDrop(const std::vector<std::string>& paths);
  void onContentScale(float scale) { content_scale_ = scale; }

  // Every key pressed since the last call, in order (repeats excluded), and clears the list.
  std::vector<int> takePresses();
  // Wheel steps since the last call.
  double takeScroll();
  // Paths dropped on the window since the last call.
  std::vector<std::string> takeDrops();
  // The window's new content scale when it changed since the last call (moved to another
  // monitor, display settings changed), else 0.
  float takeContentScale() {
    const float s = content_scale_;
    content_scale_ = 0.0f;
    return s;
  }
  // Whether `key` is down now, as the events say (for held keys: WASD).
  bool held(int key) const { return held_.count(key) != 0; }

 private:
  std::vector<int> presses_;
  std::set<int> held_;
  double scroll_ = 0.0;
  std::vector<std::string> drops_;
  float content_scale_ = 0.0f;
};

}  // namespace hv::ui

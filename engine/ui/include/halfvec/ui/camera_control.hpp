// The viewer's camera: orbit / pan / zoom / fly around Camera::target, a click (press and release
// without a drag) for picking, and F (frame the scene or the picked object). Window-free: the
// caller passes the pointer and key state (readPointer reads them from a GLFW window).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"

struct GLFWwindow;

namespace hv::ui {

struct PointerState {
  glm::dvec2 cursor{0.0};                   // window coordinates
  bool buttons[3] = {false, false, false};  // left, right, middle
};
PointerState readPointer(GLFWwindow* window);

struct FlyKeys {
  bool forward = false, back = false, left = false, right = false, up = false, down = false;
  bool fast = false;
};

class OrbitController {
 public:
  // One frame: a left drag orbits (yaw about world up, pitch kept off the poles), a right or
  // middle drag pans, `scroll` wheel steps zoom (each 10% of the distance, never closer than 1.5
  // near planes nor farther than half the far plane), held fly keys move camera and target at
  // 0.8 distances per second (4x with `fast`). Drags start only outside the UI (`ui_mouse`).
  // All speeds are relative to the distance to the target, so a millimeter model and a city
  // navigate alike.
  void update(const PointerState& p, glm::ivec2 window_size, double scroll, const FlyKeys& keys,
              bool ui_mouse, bool ui_keys, float dt, Camera& cam);

 private:
  glm::dvec2 last_{0.0};
  bool dragging_[3] = {false, false, false};
  bool first_ = true;
};

// A left click that is not a drag: pressed outside the UI and released within kSlop pixels of
// where it was pressed. Returns the release point (window coordinates) once.
class ClickDetector {
 public:
  static constexpr double kSlop = 3.0;
  std::optional<glm::dvec2> update(const PointerState& p, bool ui_mouse);

 private:
  bool down_ = false, armed_ = false;
  glm::dvec2 start_{0.0};
};

// F: the camera framing every object (object < 0) or one object from the direction it looks now,
// at the window's aspect (frameBounds of halfvec/scene/model_scene.hpp). Unchanged when there is
// nothing to frame.
void frameView(const Scene& scene, int object, float aspect, Camera& cam);

}  // namespace hv::ui

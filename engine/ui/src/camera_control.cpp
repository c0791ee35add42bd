#include "halfvec/ui/camera_control.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "halfvec/scene/model_scene.hpp"

namespace hv::ui {

PointerState readPointer(GLFWwindow* window) {
  PointerState p;
  glfwGetCursorPos(window, &p.cursor.x, &p.cursor.y);
  for (int b = 0; b < 3; ++b) p.buttons[b] = glfwGetMouseButton(window, b) == GLFW_PRESS;
  return p;
}

namespace {
glm::vec3 rotate(glm::vec3 v, glm::vec3 axis, float a) {  // Rodrigues
  return v * std::cos(a) + glm::cross(axis, v) * std::sin(a) +
         axis * glm::dot(axis, v) * (1.0f - std::cos(a));
}
}  // namespace

void OrbitController::update(const PointerState& p, glm::ivec2 window_size, double scroll,
                             const FlyKeys& keys, bool ui_mouse, bool ui_keys, float dt,
                             Camera& cam) {
  if (first_) last_ = p.cursor, first_ = false;
  const float dx = float(p.cursor.x - last_.x), dy = float(p.cursor.y - last_.y);
  last_ = p.cursor;
  glm::vec3 offset = cam.position - cam.target;
  const float dist = std::max(glm::length(offset), 1e-9f);
  const glm::vec3 fwd = -offset / dist;
  const glm::vec3 right = glm::normalize(glm::cross(fwd, cam.up));
  const glm::vec3 up = glm::cross(right, fwd);
  for (int b = 0; b < 3; ++b) {
    if (!p.buttons[b]) {
      dragging_[b] = false;
    } else if (!dragging_[b] && !ui_mouse) {
      dragging_[b] = true;  // drags start outside the UI
    }
  }
  if (dragging_[0] && (dx != 0 || dy != 0)) {
    const glm::vec3 wup = glm::normalize(cam.up);
    const float elev = std::asin(glm::clamp(glm::dot(offset / dist, wup), -1.0f, 1.0f));
    const float pitch = glm::clamp(elev - dy * 0.005f, -1.5f, 1.5f) - elev;
    const glm::vec3 o = rotate(rotate(offset / dist, right, pitch), wup, -dx * 0.005f);
    cam.position = cam.target + o * dist;
  }
  if ((dragging_[1] || dragging_[2]) && (dx != 0 || dy != 0)) {
    const float scale = 2.0f * dist * std::tan(glm::radians(cam.fov_y_deg) * 0.5f) /
                        float(std::max(window_size.y, 1));
    const glm::vec3 move = (-dx * right + dy * up) * scale;
    cam.position += move;
    cam.target += move;
  }
  if (scroll != 0.0 && !ui_mouse) {
    const float lo = 1.5f * cam.near_plane, hi = std::max(0.5f * cam.far_plane, 2.0f * lo);
    const float nd = glm::clamp(dist * std::pow(0.9f, float(scroll)), lo, hi);
    cam.position = cam.target - glm::normalize(cam.target - cam.position) * nd;
  }
  if (!ui_keys) {
    glm::vec3 v(0.0f);
    if (keys.forward) v += fwd;
    if (keys.back) v -= fwd;
    if (keys.right) v += right;
    if (keys.left) v -= right;
    if (keys.up) v += up;
    if (keys.down) v -= up;
    if (v != glm::vec3(0.0f)) {
      const glm::vec3 move = glm::normalize(v) * dist * 0.8f * (keys.fast ? 4.0f : 1.0f) * dt;
      cam.position += move;
      cam.target += move;
    }
  }
}

std::optional<glm::dvec2> ClickDetector::update(const PointerState& p, bool ui_mouse) {
  const bool now = p.buttons[0];
  std::optional<glm::dvec2> click;
  if (now && !down_) {
    armed_ = !ui_mouse;
    start_ = p.cursor;
  } else if (now && glm::length(p.cursor - start_) > kSlop) {
    armed_ = false;
  } else if (!now && down_ && armed_) {
    click = p.cursor;
  }
  down_ = now;
  return click;
}

void frameView(const Scene& scene, int object, float aspect, Camera& cam) {
  std::vector<glm::vec3> points;
  Bounds b;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    if (object >= 0 && int(i) != object) continue;
    const Object& o = scene.objects[i];
    for (int m : o.meshes) {
      for (const Vertex& v : scene.meshes[size_t(m)].vertices) {
        const glm::vec3 p = glm::vec3(o.transform * glm::vec4(v.position, 1.0f));
        points.push_back(p);
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
      }
    }
  }
  if (points.empty()) return;
  const glm::vec3 dir = glm::normalize(cam.position - cam.target);
  const float azimuth = glm::degrees(std::atan2(dir.x, dir.z));
  // Kept off the poles, where the framing basis (view direction x world up) degenerates.
  const float elevation =
      glm::clamp(glm::degrees(std::asin(glm::clamp(dir.y, -1.0f, 1.0f))), -85.0f, 85.0f);
  const Camera framed = frameBounds(points, b, azimuth, elevation, cam.fov_y_deg, aspect);
  cam.position = framed.position;
  cam.target = framed.target;
  cam.up = glm::vec3(0, 1, 0);
  cam.near_plane = framed.near_plane;
  cam.far_plane = std::max(cam.far_plane, framed.far_plane);
}

}  // namespace hv::ui

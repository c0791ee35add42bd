#include "halfvec/render/pick.hpp"

#include <algorithm>
#include <limits>

#include "halfvec/render/frame_data.hpp"

namespace hv::render {

namespace {

struct Ray {
  glm::vec3 origin, dir;  // dir need not be unit length: t is in units of |dir|
};

// Slab test: the ray's [0, t_max] span meets the box.
bool hitsBox(const Ray& r, const glm::vec3& lo, const glm::vec3& hi, float t_max) {
  float t0 = 0.0f, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    const float inv = 1.0f / r.dir[a];  // +-inf for an axis-parallel ray: the comparisons hold
    float tn = (lo[a] - r.origin[a]) * inv, tf = (hi[a] - r.origin[a]) * inv;
    if (tn > tf) std::swap(tn, tf);
    t0 = std::max(t0, tn);
    t1 = std::min(t1, tf);
    if (t0 > t1) return false;
  }
  return true;
}

// Moeller & Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection". Returns t, or
// +inf. `two_sided` false: a triangle whose counter-clockwise side faces away from the ray is
// not hit (GL_CCW front faces with back-face culling).
float hitTriangle(const Ray& r, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                  bool two_sided) {
  constexpr float kNone = std::numeric_limits<float>::infinity();
  const glm::vec3 e1 = b - a, e2 = c - a;
  const glm::vec3 p = glm::cross(r.dir, e2);
  const float det = glm::dot(e1, p);  // = -dot(cross(e1, e2), dir): > 0 when front-facing
  if (two_sided ? std::abs(det) < 1e-12f : det < 1e-12f) return kNone;
  const float inv = 1.0f / det;
  const glm::vec3 s = r.origin - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return kNone;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(r.dir, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return kNone;
  const float t = glm::dot(e2, q) * inv;
  return t > 0.0f ? t : kNone;
}

}  // namespace

std::optional<PickHit> pick(const Scene& scene, int width, int height, glm::vec2 pixel) {
  if (width <= 0 || height <= 0) return std::nullopt;
  const FrameBlock f = makeFrameBlock(scene, width, height);
  // Pixel -> NDC (GL's y points up); reversed Z: depth 1 at the near plane, 0.5 at twice it.
  const glm::vec2 ndc((pixel.x / float(width)) * 2.0f - 1.0f,
                      1.0f - (pixel.y / float(height)) * 2.0f);
  const glm::vec4 p = f.inv_view_proj * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 eye = scene.camera.position;
  const glm::vec3 dir = glm::normalize(glm::vec3(p) / p.w - eye);
  const glm::vec3 forward = glm::normalize(scene.camera.target - eye);
  // The G-buffer pass clips at the near plane (view depth), not at a distance from the eye.
  const float t_min = scene.camera.near_plane / std::max(glm::dot(dir, forward), 1e-6f);

  std::optional<PickHit> best;
  float best_t = std::numeric_limits<float>::infinity();
  for (size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const Object& o = scene.objects[oi];
    // In object space (t unchanged: the direction is transformed, not renormalized). The facing
    // test there equals the GPU's in window space, mirroring transform or not: the winding and
    // the ray flip together.
    const glm::mat4 inv = glm::inverse(o.transform);
    const Ray r{glm::vec3(inv * glm::vec4(eye, 1.0f)), glm::vec3(inv * glm::vec4(dir, 0.0f))};
    for (int mi : o.meshes) {
      if (mi < 0 || size_t(mi) >= scene.meshes.size()) continue;
      const Mesh& m = scene.meshes[size_t(mi)];
      if (m.vertices.empty()) continue;
      glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
      for (const Vertex& v : m.vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
      }
      if (!hitsBox(r, lo, hi, best_t)) continue;
      const bool two_sided = m.material >= 0 && size_t(m.material) < scene.materials.size() &&
                             scene.materials[size_t(m.material)].double_sided;
      for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const uint32_t ia = m.indices[i], ib = m.indices[i + 1], ic = m.indices[i + 2];
        if (std::max({ia, ib, ic}) >= m.vertices.size()) continue;
        const float t = hitTriangle(r, m.vertices[ia].position, m.vertices[ib].position,
                                    m.vertices[ic].position, two_sided);
        if (t < best_t && t >= t_min) {
          best_t = t;
          best = PickHit{int(oi), mi, m.material, t, eye + dir * t};
        }
      }
    }
  }
  return best;
}

size_t countLightsInView(const Scene& scene, int width, int height) {
  if (width <= 0 || height <= 0) return 0;
  const glm::mat4 m = glm::transpose(makeFrameBlock(scene, width, height).view_proj);  // rows
  // Gribb & Hartmann 2001 planes (inside: dot >= 0): left, right, bottom, top, and the near plane
  // of reversed Z (depth <= 1); the infinite projection has no far plane.
  glm::vec4 planes[5] = {m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[3] - m[2]};
  for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
  size_t n = 0;
  for (const Light& l : scene.lights) {
    if (l.type == LightType::Directional) {  // everywhere: in every view
      ++n;
      continue;
    }
    const float r = l.range + (l.type == LightType::Tube ? 0.5f * l.length : 0.0f);
    bool inside = true;
    for (const glm::vec4& p : planes)
      inside = inside && glm::dot(glm::vec3(p), l.position) + p.w >= -r;
    n += inside;
  }
  return n;
}

}  // namespace hv::render

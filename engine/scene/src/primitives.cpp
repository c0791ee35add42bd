#include "halfvec/scene/primitives.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace hv {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// glTF convention (see tangents.hpp): B = cross(N, T) * w points up the image, i.e. along -dP/dv,
// because texture v runs down the image.
float handedness(const glm::vec3& n, const glm::vec3& t, const glm::vec3& dp_dv) {
  return glm::dot(glm::cross(n, t), dp_dv) <= 0.0f ? 1.0f : -1.0f;
}

// One profile sample of a surface of revolution about +Y: colatitude theta (normal direction),
// the profile point's radius scale and height offset, and its v coordinate.
struct ProfilePoint {
  float theta;
  float y_offset;
  float v;
};

// Sweeps the profile around +Y. Normal n(theta, phi) = (sin t sin p, cos t, sin t cos p);
// position = radius * n + (0, y_offset, 0). Tangent = d/dphi direction (cos p, 0, -sin p), which
// stays defined at the poles; the v direction is d/dtheta.
Mesh revolve(float radius, int segments, const std::vector<ProfilePoint>& profile) {
  Mesh m;
  const int cols = segments + 1;
  // Sized once: a budget-sized sphere is millions of vertices, and growing by doubling would
  // copy them several times and hold twice the memory at the peak.
  m.vertices.reserve(profile.size() * size_t(cols));
  m.indices.reserve((profile.size() - 1) * size_t(segments) * 6);
  for (const ProfilePoint& pp : profile) {
    const float st = std::sin(pp.theta), ct = std::cos(pp.theta);
    for (int j = 0; j <= segments; ++j) {
      const float u = float(j) / float(segments);
      const float phi = u * 2.0f * kPi;
      const float sp = std::sin(phi), cp = std::cos(phi);
      Vertex v;
      v.normal = glm::vec3(st * sp, ct, st * cp);
      v.position = radius * v.normal + glm::vec3(0.0f, pp.y_offset, 0.0f);
      const glm::vec3 t(cp, 0.0f, -sp);
      const glm::vec3 dp_dv(ct * sp, -st, ct * cp);  // direction of increasing theta, hence v
      v.tangent = glm::vec4(t, handedness(v.normal, t, dp_dv));
      v.uv0 = v.uv1 = glm::vec2(u, pp.v);
      m.vertices.push_back(v);
    }
  }
  const int rows = int(profile.size());
  for (int i = 0; i + 1 < rows; ++i) {
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = uint32_t(i * cols + j), b = uint32_t((i + 1) * cols + j);
      const uint32_t c = b + 1, d = a + 1;
      // Quad a(top-left) b(bottom-left) c(bottom-right) d(top-right) seen from outside; skip the
      // triangle that collapses at a pole.
      if (profile[size_t(i)].theta > 0.0f) m.indices.insert(m.indices.end(), {a, b, d});
      if (profile[size_t(i) + 1].theta < kPi) m.indices.insert(m.indices.end(), {d, b, c});
    }
  }
  return m;
}

void requirePositive(float x, const char* what) {
  if (!(x > 0.0f) || !std::isfinite(x))
    throw std::invalid_argument(std::string(what) + " must be > 0");
}

}  // namespace

Mesh makeSphere(float radius, int segments, int rings) {
  requirePositive(radius, "sphere radius");
  if (segments < 3 || rings < 2)
    throw std::invalid_argument("sphere needs segments >= 3, rings >= 2");
  std::vector<ProfilePoint> profile;
  for (int i = 0; i <= rings; ++i) {
    const float v = float(i) / float(rings);
    profile.push_back({v * kPi, 0.0f, v});
  }
  Mesh m = revolve(radius, segments, profile);
  m.name = "sphere";
  return m;
}

Mesh makeCapsule(float radius, float half_length, int segments, int rings) {
  requirePositive(radius, "capsule radius");
  if (!(half_length >= 0.0f)) throw std::invalid_argument("capsule half_length must be >= 0");
  if (segments < 3 || rings < 2)
    throw std::invalid_argument("capsule needs segments >= 3, rings >= 2");
  const int half = (rings + 1) / 2;
  const float cap_len = 0.5f * kPi * radius;
  const float total = 2.0f * cap_len + 2.0f * half_length;
  std::vector<ProfilePoint> profile;
  for (int i = 0; i <= half; ++i) {  // top hemisphere, theta 0 .. pi/2
    const float f = float(i) / float(half);
    profile.push_back({f * 0.5f * kPi, half_length, f * cap_len / total});
  }
  for (int i = 0; i <= half;
       ++i) {  // bottom hemisphere, theta pi/2 .. pi (first row closes the cylinder)
    const float f = float(i) / float(half);
    profile.push_back({(0.5f + 0.5f * f) * kPi, -half_length,
                       (cap_len + 2.0f * half_length + f * cap_len) / total});
  }
  Mesh m = revolve(radius, segments, profile);
  m.name = "capsule";
  return m;
}

namespace {

// One rectangular face: centre c, u axis `t` with half size ht, v axis `b` with half size hb,
// outward normal n.
void addFace(Mesh& m, const glm::vec3& c, const glm::vec3& n, const glm::vec3& t, float ht,
             const glm::vec3& b, float hb) {
  const uint32_t base = uint32_t(m.vertices.size());
  const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const glm::vec2& uv : uvs) {
    Vertex v;
    v.position = c + t * ((uv.x * 2.0f - 1.0f) * ht) + b * ((uv.y * 2.0f - 1.0f) * hb);
    v.normal = n;
    v.tangent = glm::vec4(t, handedness(n, t, b));
    v.uv0 = v.uv1 = uv;
    m.vertices.push_back(v);
  }
  // Corners 0,1,2,3 run counter-clockwise about cross(t, b); flip when that opposes n.
  if (glm::dot(glm::cross(t, b), n) > 0.0f) {
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  } else {
    m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
  }
}

}  // namespace

Mesh makePlane(float size_x, float size_z) {
  requirePositive(size_x, "plane size_x");
  requirePositive(size_z, "plane size_z");
  Mesh m;
  m.name = "plane";
  addFace(m, glm::vec3(0.0f), {0, 1, 0}, {1, 0, 0}, 0.5f * size_x, {0, 0, 1}, 0.5f * size_z);
  return m;
}

Mesh makeBox(const glm::vec3& h) {
  requirePositive(h.x, "box half_extents.x");
  requirePositive(h.y, "box half_extents.y");
  requirePositive(h.z, "box half_extents.z");
  Mesh m;
  m.name = "box";
  // Side faces: u runs left to right and v top to bottom as seen from outside, +Y up.
  addFace(m, {h.x, 0, 0}, {1, 0, 0}, {0, 0, -1}, h.z, {0, -1, 0}, h.y);
  addFace(m, {-h.x, 0, 0}, {-1, 0, 0}, {0, 0, 1}, h.z, {0, -1, 0}, h.y);
  addFace(m, {0, 0, h.z}, {0, 0, 1}, {1, 0, 0}, h.x, {0, -1, 0}, h.y);
  addFace(m, {0, 0, -h.z}, {0, 0, -1}, {-1, 0, 0}, h.x, {0, -1, 0}, h.y);
  addFace(m, {0, h.y, 0}, {0, 1, 0}, {1, 0, 0}, h.x, {0, 0, 1}, h.z);
  addFace(m, {0, -h.y, 0}, {0, -1, 0}, {1, 0, 0}, h.x, {0, 0, -1}, h.z);
  return m;
}

int addMeshObject(Scene& scene, Mesh mesh, const Material& material, const glm::vec3& position) {
  scene.materials.push_back(material);
  mesh.material = int(scene.materials.size()) - 1;
  scene.meshes.push_back(std::move(mesh));
  Object o;
  o.meshes = {int(scene.meshes.size()) - 1};
  o.transform[3] = glm::vec4(position, 1.0f);
  scene.objects.push_back(o);
  return int(scene.objects.size()) - 1;
}

}  // namespace hv

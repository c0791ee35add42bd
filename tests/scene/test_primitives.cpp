#include <gtest/gtest.h>

#include <functional>

#include "halfvec/scene/primitives.hpp"

namespace {

void checkMesh(
    const hv::Mesh& m,
    const std::function<glm::vec3(const glm::vec3&, const glm::vec3&)>& analytic_normal) {
  ASSERT_FALSE(m.vertices.empty());
  ASSERT_EQ(m.indices.size() % 3, 0u);
  for (const hv::Vertex& v : m.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    const glm::vec3 n = analytic_normal(v.position, v.normal);
    EXPECT_NEAR(glm::dot(v.normal, n), 1.0f, 1e-4f) << "vertex normal differs from analytic";
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-5f);
    EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
  }
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const hv::Vertex& a = m.vertices[m.indices[t]];
    const hv::Vertex& b = m.vertices[m.indices[t + 1]];
    const hv::Vertex& c = m.vertices[m.indices[t + 2]];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec3 fn = glm::cross(e1, e2);
    ASSERT_GT(glm::length(fn), 0.0f) << "degenerate triangle " << t / 3;
    const glm::vec3 avg_n = a.normal + b.normal + c.normal;
    EXPECT_GT(glm::dot(fn, avg_n), 0.0f) << "triangle " << t / 3 << " is clockwise from outside";
    // Tangent frame agrees with the UV derivatives: T along +u, cross(N,T)*w along -v (up the
    // image: glTF's convention, tangents.hpp).
    const glm::vec2 d1 = b.uv0 - a.uv0, d2 = c.uv0 - a.uv0;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-12f) continue;
    const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
    EXPECT_GT(glm::dot(glm::vec3(a.tangent), dpdu), 0.0f);
    EXPECT_LT(glm::dot(glm::cross(a.normal, glm::vec3(a.tangent)) * a.tangent.w, dpdv), 0.0f);
  }
}

}  // namespace

TEST(Primitives, Sphere) {
  checkMesh(hv::makeSphere(0.7f, 24, 12),
            [](const glm::vec3& p, const glm::vec3&) { return glm::normalize(p); });
}

TEST(Primitives, Plane) {
  checkMesh(hv::makePlane(2.0f, 3.0f),
            [](const glm::vec3&, const glm::vec3&) { return glm::vec3(0, 1, 0); });
}

TEST(Primitives, Box) {
  const glm::vec3 h(0.5f, 1.0f, 1.5f);
  // Edge and corner positions lie on several faces: the analytic normal is the axis direction
  // of the face the vertex claims, provided the vertex lies in that face's plane.
  checkMesh(hv::makeBox(h), [&](const glm::vec3& p, const glm::vec3& claimed) {
    for (int i = 0; i < 3; ++i) {
      for (float s : {-1.0f, 1.0f}) {
        glm::vec3 n(0.0f);
        n[i] = s;
        if (glm::dot(claimed, n) > 0.5f && std::abs(p[i] - s * h[i]) < 1e-6f) return n;
      }
    }
    return glm::vec3(0.0f);
  });
}

TEST(Primitives, Capsule) {
  const float r = 0.3f, hl = 0.6f;
  checkMesh(hv::makeCapsule(r, hl, 24, 12), [&](const glm::vec3& p, const glm::vec3&) {
    const glm::vec3 c(0.0f, glm::clamp(p.y, -hl, hl), 0.0f);
    return glm::normalize(p - c);
  });
}

TEST(Primitives, AddMeshObjectLinksMaterialMeshAndObject) {
  hv::Scene s;
  hv::Material a, b;
  a.roughness = 0.2f;
  b.roughness = 0.9f;
  EXPECT_EQ(hv::addMeshObject(s, hv::makeBox(glm::vec3(1.0f)), a, glm::vec3(0.0f)), 0);
  EXPECT_EQ(hv::addMeshObject(s, hv::makeSphere(1.0f, 8, 4), b, {1.0f, 2.0f, 3.0f}), 1);
  ASSERT_EQ(s.materials.size(), 2u);
  ASSERT_EQ(s.meshes.size(), 2u);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[1].meshes, std::vector<int>{1});
  EXPECT_EQ(s.meshes[1].material, 1);
  EXPECT_EQ(s.materials[1].roughness, 0.9f);
  EXPECT_EQ(s.objects[1].transform[3], glm::vec4(1.0f, 2.0f, 3.0f, 1.0f));
  EXPECT_EQ(s.objects[1].transform[0], glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
}

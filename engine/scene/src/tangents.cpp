#include "tangents.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace hv {
namespace {

// Any unit vector perpendicular to n (n unit length).
glm::vec3 anyPerpendicular(const glm::vec3& n) {
  const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(a, n));
}

}  // namespace

void generateTangents(Mesh& mesh, int texcoord) {
  const size_t nv = mesh.vertices.size();
  auto uv = [&](uint32_t i) { return texcoord == 1 ? mesh.vertices[i].uv1 : mesh.vertices[i].uv0; };
  // accum[v][0] gathers triangles of handedness +1, accum[v][1] those of -1.
  std::vector<glm::vec3> accum(nv * 2, glm::vec3(0.0f));
  std::vector<uint8_t> used(nv * 2, 0);
  std::vector<uint8_t> tri_side(mesh.indices.size() / 3, 0);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t idx[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    const glm::vec3 p0 = mesh.vertices[idx[0]].position;
    const glm::vec3 e1 = mesh.vertices[idx[1]].position - p0;
    const glm::vec3 e2 = mesh.vertices[idx[2]].position - p0;
    const glm::vec2 d1 = uv(idx[1]) - uv(idx[0]);
    const glm::vec2 d2 = uv(idx[2]) - uv(idx[0]);
    const float det = d1.x * d2.y - d2.x * d1.y;
    glm::vec3 tan(0.0f), bit(0.0f);
    if (std::abs(det) > 1e-20f) {
      tan = (e1 * d2.y - e2 * d1.y) / det;  // dP/du
      bit = (e2 * d1.x - e1 * d2.x) / det;  // dP/dv
    }
    const glm::vec3 face_n = glm::cross(e1, e2);
    // The orientation of the UV map relative to the geometric face decides handedness. glTF's v
    // runs down the image while a normal map's green channel points up it (MikkTSpace's v-up
    // convention), so B = cross(N, T) * w must point along -dP/dv: side 0 (w = +1) when it does.
    const int side = glm::dot(glm::cross(face_n, tan), bit) <= 0.0f ? 0 : 1;
    tri_side[t / 3] = uint8_t(side);
    for (int c = 0; c < 3; ++c) {
      const Vertex& v = mesh.vertices[idx[c]];
      const glm::vec3 a = mesh.vertices[idx[(c + 1) % 3]].position - v.position;
      const glm::vec3 b = mesh.vertices[idx[(c + 2) % 3]].position - v.position;
      const float la = glm::length(a), lb = glm::length(b);
      float angle = 0.0f;
      if (la > 0.0f && lb > 0.0f)
        angle = std::acos(glm::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
      const glm::vec3 proj = tan - v.normal * glm::dot(v.normal, tan);
      const float lp = glm::length(proj);
      if (lp > 0.0f) accum[idx[c] * 2 + size_t(side)] += proj / lp * angle;
      used[idx[c] * 2 + size_t(side)] = 1;
    }
  }
  auto finish = [](const glm::vec3& n, const glm::vec3& sum, float w) {
    glm::vec3 t = sum - n * glm::dot(n, sum);  // Gram-Schmidt
    const float l = glm::length(t);
    return glm::vec4(l > 1e-12f ? t / l : anyPerpendicular(n), w);
  };
  std::vector<uint32_t> split(nv, 0);  // index of the -1 copy of a vertex used by both sides
  for (size_t v = 0; v < nv; ++v) {
    Vertex& vert = mesh.vertices[v];
    if (used[v * 2] || !used[v * 2 + 1]) {
      vert.tangent = finish(vert.normal, accum[v * 2], 1.0f);
      if (used[v * 2 + 1]) {
        Vertex copy = vert;
        copy.tangent = finish(vert.normal, accum[v * 2 + 1], -1.0f);
        split[v] = uint32_t(mesh.vertices.size());
        mesh.vertices.push_back(copy);  // may reallocate: `vert` not used after this
      }
    } else {
      vert.tangent = finish(vert.normal, accum[v * 2 + 1], -1.0f);
    }
  }
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    if (tri_side[t / 3] != 1) continue;
    for (size_t c = 0; c < 3; ++c) {
      const uint32_t i = mesh.indices[t + c];
      if (i < nv && split[i] != 0) mesh.indices[t + c] = split[i];
    }
  }
}

}  // namespace hv

// Primitives into meshes: the attributes (POSITION, NORMAL, TANGENT, TEXCOORD_0/1, COLOR_0), the
// indices and the modes converted to triangle lists, the file's budgets, the vertices (flat
// normals when NORMAL is missing) and the generated tangents.
#include "gltf_import.hpp"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "tangents.hpp"

namespace hv::gltf {
namespace {

// The accessor of attribute `name`, -1 when the primitive has none.
int attribute(const tinygltf::Primitive& p, const char* name) {
  auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

// `triangles` triangles of `mode` (TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN) as a list.
std::vector<uint32_t> triangleList(int mode, std::vector<uint32_t> ind, size_t triangles) {
  if (mode == TINYGLTF_MODE_TRIANGLES) return ind;
  std::vector<uint32_t> tris;
  tris.reserve(3 * triangles);
  for (size_t i = 0; i < triangles; ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // glTF spec 3.7.2.1 ordering
      tris.insert(tris.end(), {ind[i], ind[i + 1 + i % 2], ind[i + 2 - i % 2]});
    } else {
      tris.insert(tris.end(), {ind[i + 1], ind[i + 2], ind[0]});
    }
  }
  return tris;
}

Vertex makeVertex(const PrimitiveAttributes& a, size_t i) {
  Vertex v;
  v.position = glm::make_vec3(&a.pos[i * 3]);
  if (a.has_normal) {
    v.normal = glm::make_vec3(&a.nrm[i * 3]);
    const float l = glm::length(v.normal);
    v.normal = l > 1e-12f ? v.normal / l : glm::vec3(0, 1, 0);
  }
  if (!a.tan.empty()) {
    v.tangent = glm::make_vec4(&a.tan[i * 4]);
    v.tangent.w = v.tangent.w < 0.0f ? -1.0f : 1.0f;
  }
  if (!a.uv[0].empty()) v.uv0 = glm::make_vec2(&a.uv[0][i * 2]);
  if (!a.uv[1].empty()) v.uv1 = glm::make_vec2(&a.uv[1][i * 2]);
  if (!a.col.empty()) {
    const float* c = &a.col[i * a.col_comps];
    // Float colours outside [0, 1] are invalid glTF: clamped, as a base colour is.
    v.color = glm::clamp(glm::vec4(c[0], c[1], c[2], a.col_comps == 4 ? c[3] : 1.0f), 0.0f, 1.0f);
  }
  return v;
}

// The vertices and indices of `mesh` from the attributes and the triangle list `tris`.
void buildVertices(Mesh& mesh, const PrimitiveAttributes& a, std::vector<uint32_t> tris) {
  if (a.has_normal) {
    mesh.vertices.reserve(a.n);
    for (size_t i = 0; i < a.n; ++i) mesh.vertices.push_back(makeVertex(a, i));
    mesh.indices = std::move(tris);
    return;
  }
  // Flat normals: every triangle gets its own three vertices.
  mesh.vertices.reserve(tris.size());
  mesh.indices.reserve(tris.size());
  for (size_t t = 0; t + 2 < tris.size(); t += 3) {
    Vertex v[3] = {makeVertex(a, tris[t]), makeVertex(a, tris[t + 1]), makeVertex(a, tris[t + 2])};
    glm::vec3 fn = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
    const float l = glm::length(fn);
    fn = l > 0.0f ? fn / l : glm::vec3(0, 1, 0);
    for (Vertex& x : v) {
      x.normal = fn;
      mesh.indices.push_back(uint32_t(mesh.vertices.size()));
      mesh.vertices.push_back(x);
    }
  }
}

}  // namespace

void Importer::importMesh(int mi) {
  const tinygltf::Mesh& gm = m_.meshes[size_t(mi)];
  for (size_t pi = 0; pi < gm.primitives.size(); ++pi) {
    const std::string el =
        "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
    std::optional<Mesh> mesh = importPrimitive(gm.primitives[pi], el);
    if (!mesh) continue;
    mesh_triangles_[size_t(mi)] += mesh->indices.size() / 3;
    mesh->name =
        (gm.name.empty() ? "mesh" + std::to_string(mi) : gm.name) + "/" + std::to_string(pi);
    meshes.push_back(std::move(*mesh));
    mesh_map_[size_t(mi)].push_back(mesh_base_ + int(meshes.size()) - 1);
  }
}

std::optional<Mesh> Importer::importPrimitive(const tinygltf::Primitive& p, const std::string& el) {
  const int pos_acc = attribute(p, "POSITION");
  // glTF 2.0 (3.7.2.1): without positions a client "SHOULD skip primitive's rendering" (the
  // Khronos validator accepts such a file, with a warning).
  if (pos_acc < 0) {
    warn(el + ": no POSITION attribute (nothing to draw); skipped");
    return std::nullopt;
  }
  const PrimitiveAttributes a = readAttributes(p, pos_acc, el);
  std::vector<uint32_t> ind;
  if (p.indices >= 0) {
    ind = readIndices(p.indices, a.n, el + ".indices");
  } else {
    ind.resize(a.n);
    for (size_t i = 0; i < a.n; ++i) ind[i] = uint32_t(i);
  }
  const std::optional<size_t> triangles = triangleCount(p, ind.size(), el);
  if (!triangles) return std::nullopt;
  countBudgets(*triangles, a, el);
  std::vector<uint32_t> tris = triangleList(p.mode, std::move(ind), *triangles);

  Mesh mesh;
  mesh.material = primitiveMaterial(p, el);
  int normal_set = 0;
  if (opt_.material_override < 0 && p.material >= 0) {
    normal_set = materials[size_t(p.material)].normal_tex.texcoord;
  }
  mesh.has_colors = !a.col.empty();
  buildVertices(mesh, a, std::move(tris));
  // Provided tangents are ignored when normals were missing (glTF 2.0, 3.7.2.1).
  if (a.tan.empty() || !a.has_normal) generateTangents(mesh, normal_set);
  return mesh;
}

// The vertex attributes, each accessor checked (type, component type, normalization, count).
PrimitiveAttributes Importer::readAttributes(const tinygltf::Primitive& p, int pos_acc,
                                             const std::string& el) {
  // The vertex budget before any attribute is read (they may have no bufferView: zeros).
  const uint64_t pos_count = accessor(pos_acc, el + ".POSITION").count;
  if (pos_count > lim_.max_vertices - std::min(total_vertices_, lim_.max_vertices)) {
    fail(idx("accessors", size_t(pos_acc)) + ".count",
         std::to_string(pos_count) + " vertices (" + el +
             ".POSITION) exceed the file's budget of " + std::to_string(lim_.max_vertices) +
             " (GltfLimits::max_vertices)");
  }
  auto attr = [&](const char* name) { return attribute(p, name); };
  constexpr int kF = TINYGLTF_COMPONENT_TYPE_FLOAT, kUB = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                kB = TINYGLTF_COMPONENT_TYPE_BYTE, kUS = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                kS = TINYGLTF_COMPONENT_TYPE_SHORT;
  PrimitiveAttributes a;
  a.pos =
      readFloats(pos_acc, el + ".POSITION", {TINYGLTF_TYPE_VEC3}, {kF, kB, kUB, kS, kUS}, false);
  const size_t n = a.n = a.pos.size() / 3;
  a.has_normal = attr("NORMAL") >= 0;
  if (a.has_normal)
    a.nrm = readFloats(attr("NORMAL"), el + ".NORMAL", {TINYGLTF_TYPE_VEC3}, {kF, kB, kS}, true);
  if (a.has_normal && attr("TANGENT") >= 0) {
    a.tan = readFloats(attr("TANGENT"), el + ".TANGENT", {TINYGLTF_TYPE_VEC4}, {kF, kB, kS}, true);
  }
  for (int s = 0; s < 2; ++s) {
    const std::string name = "TEXCOORD_" + std::to_string(s);
    if (attr(name.c_str()) >= 0) {
      a.uv[s] = readFloats(attr(name.c_str()), el + "." + name, {TINYGLTF_TYPE_VEC2},
                           {kF, kUB, kUS, kB, kS}, true);
    }
  }
  // glTF 2.0 3.7.2.1: COLOR_0 is VEC3 or VEC4 of float, or normalized unsigned byte/short;
  // linear RGB(A), multiplying the base colour (and alpha).
  if (attr("COLOR_0") >= 0) {
    a.col = readFloats(attr("COLOR_0"), el + ".COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                       {kF, kUB, kUS}, true);
    a.col_comps = accessor(attr("COLOR_0"), el + ".COLOR_0").type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
  }
  auto sizeCheck = [&](const std::vector<float>& v, size_t comps, const char* what) {
    if (!v.empty() && v.size() != n * comps) {
      fail(el + "." + what, "count differs from POSITION count " + std::to_string(n));
    }
  };
  sizeCheck(a.nrm, 3, "NORMAL");
  sizeCheck(a.tan, 4, "TANGENT");
  sizeCheck(a.uv[0], 2, "TEXCOORD_0");
  sizeCheck(a.uv[1], 2, "TEXCOORD_1");
  sizeCheck(a.col, a.col_comps, "COLOR_0");
  return a;
}

// The triangles `index_count` indices make in the primitive's mode; none (a warning) for points
// and lines, which are validated but not drawn.
std::optional<size_t> Importer::triangleCount(const tinygltf::Primitive& p, size_t index_count,
                                              const std::string& el) const {
  switch (p.mode) {
    case TINYGLTF_MODE_TRIANGLES:
      if (index_count % 3 != 0) fail(el, "TRIANGLES index count is not a multiple of 3");
      return index_count / 3;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
    case TINYGLTF_MODE_TRIANGLE_FAN:
      return index_count >= 3 ? index_count - 2 : 0;
    case TINYGLTF_MODE_POINTS:
    case TINYGLTF_MODE_LINE:
    case TINYGLTF_MODE_LINE_LOOP:
    case TINYGLTF_MODE_LINE_STRIP:
      warn(el + ": mode " + std::to_string(p.mode) + " (points/lines) is not rendered; skipped");
      return std::nullopt;
    default:
      fail(el + ".mode", "unknown value " + std::to_string(p.mode));
  }
}

// The file's budgets of triangles and vertices, before the triangle list and the vertices are
// built.
void Importer::countBudgets(size_t triangles, const PrimitiveAttributes& a, const std::string& el) {
  total_triangles_ += triangles;
  total_vertices_ += a.has_normal ? a.n : 3 * triangles;  // without normals: 3 per triangle
  if (total_triangles_ > lim_.max_triangles) {
    fail(el, "the file's triangles exceed the budget of " + std::to_string(lim_.max_triangles) +
                 " (GltfLimits::max_triangles)");
  }
  if (total_vertices_ > lim_.max_vertices) {
    fail(el, "the file's vertices exceed the budget of " + std::to_string(lim_.max_vertices) +
                 " (GltfLimits::max_vertices)");
  }
}

// The scene material of the primitive: its own, the override, or the glTF default material.
int Importer::primitiveMaterial(const tinygltf::Primitive& p, const std::string& el) {
  if (p.material < 0) return defaultMaterial();
  if (p.material >= int(m_.materials.size())) {
    fail(el + ".material", "index " + std::to_string(p.material) + " out of range");
  }
  return opt_.material_override >= 0 ? opt_.material_override : material_base_ + p.material;
}

}  // namespace hv::gltf

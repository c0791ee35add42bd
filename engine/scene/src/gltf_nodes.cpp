// The node walk: the scene's roots, node transforms (matrix or TRS), the budgets of the graph's
// expansion, the depth-first walk that instances meshes as objects, and camera nodes.
#include "gltf_import.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace hv::gltf {
namespace {

namespace fs = std::filesystem;

// Scene coordinates and sizes (metres) stay within +-1e6, as in scene files (kBig there).
constexpr float kMaxWorldExtent = 1e6f;

bool allFinite(const glm::mat3& m) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

}  // namespace

// The root nodes of the default scene (else scene 0); `roots_el` names the list, for messages.
std::vector<int> Importer::sceneRoots(std::string& roots_el) const {
  std::vector<int> roots;
  if (!m_.scenes.empty()) {
    const int s = m_.defaultScene >= 0 ? m_.defaultScene : 0;
    if (s >= int(m_.scenes.size())) fail("scene", "index " + std::to_string(s) + " out of range");
    roots = m_.scenes[size_t(s)].nodes;
    roots_el = idx("scenes", size_t(s)) + ".nodes";
  } else {  // no scenes: every node that is nobody's child is a root
    std::vector<bool> child(m_.nodes.size(), false);
    for (const auto& n : m_.nodes)
      for (int c : n.children)
        if (c >= 0 && c < int(child.size())) child[size_t(c)] = true;
    for (size_t i = 0; i < m_.nodes.size(); ++i)
      if (!child[i]) roots.push_back(int(i));
    roots_el = "nodes";
  }
  return roots;
}

glm::mat4 Importer::localMatrix(const tinygltf::Node& n, const std::string& el) const {
  glm::mat4 local(1.0f);
  if (n.matrix.size() == 16) {
    for (int k = 0; k < 16; ++k) {
      glm::value_ptr(local)[k] = finite(n.matrix[size_t(k)], el + ".matrix");
    }
    return local;
  }
  glm::mat4 t(1.0f), r(1.0f), s(1.0f);
  if (n.translation.size() == 3) {
    const std::string f = el + ".translation";
    t = glm::translate(glm::mat4(1.0f),
                       glm::vec3(finite(n.translation[0], f), finite(n.translation[1], f),
                                 finite(n.translation[2], f)));
  }
  if (n.rotation.size() == 4) {
    const std::string f = el + ".rotation";
    const glm::quat q(finite(n.rotation[3], f), finite(n.rotation[0], f), finite(n.rotation[1], f),
                      finite(n.rotation[2], f));
    if (!(glm::length(q) > 1e-6f)) fail(f, "expected a non-zero quaternion");
    r = glm::mat4_cast(glm::normalize(q));
  }
  if (n.scale.size() == 3) {
    const std::string f = el + ".scale";
    s = glm::scale(glm::mat4(1.0f),
                   glm::vec3(finite(n.scale[0], f), finite(n.scale[1], f), finite(n.scale[2], f)));
  }
  return t * r * s;
}

// The budgets of node instances and instanced triangles, checked before anything is instanced:
// per node, the instances and triangles of its subtree, counted once per node over the graph
// (O(nodes + children) however often a node is reused) and saturating at the budgets. A few KB
// whose 64 nodes each list the next one 4 times (4^63 instances) are rejected at once instead
// of after a million instances have been built (9 s). A child that is out of range or closes a
// cycle counts 0 here and is left to visit(), which names it (before it has instanced more than
// these totals); with neither, visit() instances exactly these totals, so it checks no budget of
// its own.
void Importer::checkExpansion(const std::vector<int>& roots) {
  const size_t n = m_.nodes.size();
  auto capOf = [](uint64_t limit) { return std::max(limit, limit + 1); };  // limit + 1, no wrap
  const uint64_t cap_i = capOf(lim_.max_node_instances);
  const uint64_t cap_t = capOf(lim_.max_instanced_triangles);
  auto add = [](uint64_t a, uint64_t b, uint64_t cap) { return b > cap - a ? cap : a + b; };
  std::vector<uint64_t> inst(n, 0), tris(n, 0);
  std::vector<uint8_t> state(n, 0);              // 0 not seen, 1 on the current path, 2 counted
  std::vector<std::pair<size_t, size_t>> stack;  // node, next child
  uint64_t total_i = 0, total_t = 0;
  for (int r : roots) {
    if (r < 0 || size_t(r) >= n) continue;
    if (state[size_t(r)] == 0) {
      state[size_t(r)] = 1;
      stack.push_back({size_t(r), 0});
    }
    while (!stack.empty()) {
      const size_t ni = stack.back().first;
      const tinygltf::Node& node = m_.nodes[ni];
      if (stack.back().second < node.children.size()) {
        const int c = node.children[stack.back().second++];
        if (c >= 0 && size_t(c) < n && state[size_t(c)] == 0) {
          state[size_t(c)] = 1;
          stack.push_back({size_t(c), 0});
        }
        continue;
      }
      uint64_t i = 1, t = 0;
      if (node.mesh >= 0 && size_t(node.mesh) < mesh_triangles_.size()) {
        t = std::min(cap_t, mesh_triangles_[size_t(node.mesh)]);
      }
      for (int c : node.children) {
        if (c < 0 || size_t(c) >= n || state[size_t(c)] != 2) continue;
        i = add(i, inst[size_t(c)], cap_i);
        t = add(t, tris[size_t(c)], cap_t);
      }
      inst[ni] = i;
      tris[ni] = t;
      state[ni] = 2;
      stack.pop_back();
    }
    total_i = add(total_i, inst[size_t(r)], cap_i);
    total_t = add(total_t, tris[size_t(r)], cap_t);
    const std::string el = idx("nodes", size_t(r));
    if (total_i > lim_.max_node_instances) {
      fail(el, "the node graph expands into more than " + std::to_string(lim_.max_node_instances) +
                   " node instances (GltfLimits::max_node_instances; nodes reused by several "
                   "parents count once per use)");
    }
    if (total_t > lim_.max_instanced_triangles) {
      fail(el, "the instanced meshes exceed the budget of " +
                   std::to_string(lim_.max_instanced_triangles) +
                   " triangles (GltfLimits::max_instanced_triangles; nodes reused by several "
                   "parents count once per use)");
    }
  }
}

// Depth-first over the node graph from root `root` with an explicit stack (a file controls
// the depth), rejecting cycles; nodes reused by several parents are instanced (checkExpansion
// has checked the budgets of node instances and instanced triangles).
void Importer::visit(int root, const glm::mat4& parent, const std::string& from) {
  struct Frame {
    int node;
    glm::mat4 world;
    size_t next_child;
  };
  std::vector<bool> on_path(m_.nodes.size(), false);
  std::vector<Frame> stack;
  auto enter = [&](int ni, const glm::mat4& parent_world, const std::string& ref) {
    if (ni < 0 || size_t(ni) >= m_.nodes.size()) {
      fail(ref, "node index " + std::to_string(ni) + " out of range (" +
                    std::to_string(m_.nodes.size()) + " nodes)");
    }
    const std::string el = idx("nodes", size_t(ni));
    if (on_path[size_t(ni)]) fail(ref, "node hierarchy contains a cycle through " + el);
    if (int(stack.size()) >= lim_.max_node_depth) {
      fail(ref, "node hierarchy deeper than " + std::to_string(lim_.max_node_depth) +
                    " levels (GltfLimits::max_node_depth)");
    }
    const tinygltf::Node& n = m_.nodes[size_t(ni)];
    // Messages name the node by index and, when it has one, by name.
    const std::string label = n.name.empty() ? el : el + " (\"" + n.name + "\")";
    const glm::mat4 world = nodeWorld(n, parent_world, el, label);
    instanceNode(n, world, el, label);
    on_path[size_t(ni)] = true;
    stack.push_back({ni, world, 0});
  };
  enter(root, parent, from);
  while (!stack.empty()) {
    Frame& f = stack.back();
    const tinygltf::Node& n = m_.nodes[size_t(f.node)];
    if (f.next_child < n.children.size()) {
      const int child = n.children[f.next_child];
      const std::string ref =
          idx("nodes", size_t(f.node)) + ".children[" + std::to_string(f.next_child) + "]";
      ++f.next_child;
      const glm::mat4 world = f.world;  // `f` may move when the stack grows
      enter(child, world, ref);
    } else {
      on_path[size_t(f.node)] = false;
      stack.pop_back();
    }
  }
}

// The node's world transform, checked to be finite and within the scene's range.
glm::mat4 Importer::nodeWorld(const tinygltf::Node& n, const glm::mat4& parent_world,
                              const std::string& el, const std::string& label) const {
  const glm::mat4 world = parent_world * localMatrix(n, el);
  for (int k = 0; k < 16; ++k) {
    if (!std::isfinite(glm::value_ptr(world)[k])) {
      fail(label, "world transform overflows (non-finite)");
    }
  }
  // Scene coordinates stay within +-1e6 m (docs/scene-format.md "Bounded"): a node placed or
  // scaled past that (a translation of 1e38) is reported here, not later by the camera
  // framed around it.
  for (int c = 0; c < 4; ++c) {
    const glm::vec3 t = glm::abs(glm::vec3(world[3]));
    const float extent = c < 3 ? glm::length(glm::vec3(world[c])) : std::max({t.x, t.y, t.z});
    if (!(extent <= kMaxWorldExtent)) {
      fail(label, std::string(c < 3 ? "world scale " : "world translation ") +
                      "beyond the scene's range of +-1e6 m (" + (c < 3 ? "axis length " : "") +
                      fmtFloat(extent) + ")");
    }
  }
  return world;
}

// The node's mesh as an object and its camera, unless its transform is singular.
void Importer::instanceNode(const tinygltf::Node& n, const glm::mat4& world, const std::string& el,
                            const std::string& label) {
  // A singular transform (a scale of 0, an all-zero matrix: valid glTF, used to hide a node)
  // draws nothing, and its normals have no inverse transpose: its meshes and cameras are
  // skipped, the node and its children are still checked.
  const bool singular = !(std::abs(glm::determinant(glm::mat3(world))) > 0.0f) ||
                        !allFinite(glm::inverse(glm::mat3(world)));
  if (singular && n.mesh >= 0 && !warned_singular_) {
    warn(label + ": a singular transform (scale 0) hides its mesh; not drawn" +
         std::string(" (nor any other mesh under a singular transform)"));
    warned_singular_ = true;
  }
  if (n.mesh >= 0 && !singular) {
    if (size_t(n.mesh) >= m_.meshes.size()) {
      fail(el + ".mesh", "index " + std::to_string(n.mesh) + " out of range");
    }
    if (!mesh_map_[size_t(n.mesh)].empty()) {
      Object o;
      o.name = (opt_.name_prefix.empty() ? fs::path(path_).stem().string() : opt_.name_prefix) +
               "/" + (n.name.empty() ? el : n.name);
      o.transform = world;
      o.meshes = mesh_map_[size_t(n.mesh)];
      objects.push_back(std::move(o));
    }
  }
  if (n.camera >= 0 && size_t(n.camera) < m_.cameras.size() && !singular) {
    addCamera(m_.cameras[size_t(n.camera)], world);
  }
  importNodeLight(n, world, el);
}

void Importer::addCamera(const tinygltf::Camera& c, const glm::mat4& world) {
  GltfCamera cam;
  cam.name = c.name;
  cam.world = world;
  cam.perspective = c.type != "orthographic";
  if (cam.perspective) {
    if (c.perspective.yfov > 0.0) cam.yfov_rad = float(c.perspective.yfov);
    if (c.perspective.znear > 0.0) cam.znear = float(c.perspective.znear);
    cam.zfar = float(std::max(c.perspective.zfar, 0.0));
  } else {
    cam.znear = float(std::max(c.orthographic.znear, 1e-4));
    cam.zfar = float(std::max(c.orthographic.zfar, 0.0));
  }
  cameras.push_back(cam);
}

}  // namespace hv::gltf

// The import's order (extensions, images, materials, meshes, then the node walk) and what it
// does not import: one warning per extension, attribute or feature, where it is first seen.
#include "gltf_import.hpp"

#include <cmath>
#include <limits>

namespace hv::gltf {

void Importer::run(const glm::mat4& transform) {
  for (size_t i = 0; i < m_.extensionsRequired.size(); ++i) {
    const std::string& ext = m_.extensionsRequired[i];
    if (!honoured(ext)) {
      fail(idx("extensionsRequired", i), "the required extension " + ext +
                                             " is not supported (supported: " + honouredList() +
                                             ")");
    }
  }
  for (size_t i = 0; i < m_.extensionsUsed.size(); ++i) {
    noteExtension(m_.extensionsUsed[i], idx("extensionsUsed", i));
  }
  checkUnsupportedStructure();
  if (opt_.material_override < 0) {
    for (size_t i = 0; i < m_.images.size(); ++i) importImage(int(i));
    for (size_t i = 0; i < m_.materials.size(); ++i) importMaterial(int(i));
  }
  mesh_map_.assign(m_.meshes.size(), {});
  mesh_triangles_.assign(m_.meshes.size(), 0);
  // Every mesh is validated even if no node uses it.
  for (size_t i = 0; i < m_.meshes.size(); ++i) importMesh(int(i));
  std::string roots_el;
  const std::vector<int> roots = sceneRoots(roots_el);
  checkExpansion(roots);
  for (int r : roots) visit(r, transform, roots_el);
}

bool Importer::honoured(const std::string& ext) {
  for (const char* h : kHonouredExtensions)
    if (ext == h) return true;
  return false;
}

std::string Importer::honouredList() {
  std::string t;
  for (const char* h : kHonouredExtensions) {
    if (!t.empty()) t += ", ";
    t += h;
  }
  return t;
}

// An extension the importer does not read, used at `el`: one warning per name per file, where
// it is first seen (extensionsUsed, or the object of a file that forgot to declare it).
void Importer::noteExtension(const std::string& ext, const std::string& el) {
  if (honoured(ext) || !warned_.insert("extension " + ext).second) return;
  warn(el + ": extension " + ext + " is not supported; ignored (the model renders without it)");
}

void Importer::noteExtensions(const tinygltf::ExtensionMap& exts, const std::string& el) {
  for (const auto& [name, value] : exts) noteExtension(name, el + ".extensions");
}

void Importer::warnOnce(const std::string& key, const std::string& msg) {
  if (warned_.insert(key).second) warn(msg);
}

// Skins, animations and morph targets are not applied: the rest pose is drawn.
void Importer::checkUnsupportedStructure() {
  if (!m_.skins.empty()) {
    warnOnce("skins", "skins: " + std::to_string(m_.skins.size()) +
                          " skin(s) not applied (skinning is not supported); the bind pose is "
                          "drawn");
  }
  if (!m_.animations.empty()) {
    warnOnce("animations", "animations: " + std::to_string(m_.animations.size()) +
                               " animation(s) not played (not supported); the static pose is "
                               "drawn");
  }
  for (size_t i = 0; i < m_.nodes.size(); ++i)
    noteExtensions(m_.nodes[i].extensions, idx("nodes", i));
  for (size_t i = 0; i < m_.textures.size(); ++i) {
    noteExtensions(m_.textures[i].extensions, idx("textures", i));
  }
  for (size_t i = 0; i < m_.images.size(); ++i)
    noteExtensions(m_.images[i].extensions, idx("images", i));
  for (size_t i = 0; i < m_.samplers.size(); ++i) {
    noteExtensions(m_.samplers[i].extensions, idx("samplers", i));
  }
  for (size_t i = 0; i < m_.cameras.size(); ++i) {
    noteExtensions(m_.cameras[i].extensions, idx("cameras", i));
  }
  for (size_t i = 0; i < m_.scenes.size(); ++i)
    noteExtensions(m_.scenes[i].extensions, idx("scenes", i));
  checkUnsupportedPrimitives();
}

// Per mesh and primitive: extensions, morph targets, attributes other than those imported.
void Importer::checkUnsupportedPrimitives() {
  for (size_t i = 0; i < m_.meshes.size(); ++i) {
    const tinygltf::Mesh& gm = m_.meshes[i];
    noteExtensions(gm.extensions, idx("meshes", i));
    for (size_t pi = 0; pi < gm.primitives.size(); ++pi) {
      const tinygltf::Primitive& p = gm.primitives[pi];
      const std::string el = idx("meshes", i) + ".primitives[" + std::to_string(pi) + "]";
      noteExtensions(p.extensions, el);
      if (!p.targets.empty()) {
        warnOnce("targets", el + ".targets: morph targets are not applied (not supported); "
                                 "the base shape is drawn");
      }
      for (const auto& [name, acc] : p.attributes) {
        if (name == "POSITION" || name == "NORMAL" || name == "TANGENT" || name == "TEXCOORD_0" ||
            name == "TEXCOORD_1" || name == "COLOR_0") {
          continue;
        }
        warnOnce("attribute " + name,
                 el + ".attributes." + name + ": attribute not supported; ignored" +
                     (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0
                          ? " (skinning is not supported)"
                          : ""));
      }
    }
  }
}

// A glTF number as a finite float, else an error naming `el`.
float Importer::finite(double x, const std::string& el) const {
  if (!std::isfinite(x) || std::abs(x) > double(std::numeric_limits<float>::max())) {
    fail(el, "expected a finite number, got " + std::to_string(x));
  }
  return float(x);
}

// A number of an extension's object (`v` has `key`), finite, else an error naming `el.key`.
float Importer::extNumber(const tinygltf::Value& v, const char* key, const std::string& el) const {
  const tinygltf::Value& x = v.Get(key);
  if (!x.IsNumber()) fail(el + "." + key, "expected a number");
  return finite(x.GetNumberAsDouble(), el + "." + key);
}

glm::vec2 Importer::extVec2(const tinygltf::Value& v, const char* key,
                            const std::string& el) const {
  const tinygltf::Value& x = v.Get(key);
  if (!x.IsArray() || x.ArrayLen() != 2 || !x.Get(0).IsNumber() || !x.Get(1).IsNumber()) {
    fail(el + "." + key, "expected an array of 2 numbers");
  }
  return {finite(x.Get(0).GetNumberAsDouble(), el + "." + key),
          finite(x.Get(1).GetNumberAsDouble(), el + "." + key)};
}

}  // namespace hv::gltf

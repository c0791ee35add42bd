// Analytic meshes for scene-file primitives. All are centred on the origin, +Y up, with exact
// analytic normals and tangents (not derived from the triangles). Winding is counter-clockwise
// seen from outside. Tangent convention (same as the glTF tangent generator, see tangents.hpp):
// tangent.xyz points along +u, and cross(normal, tangent.xyz) * tangent.w points along +v.
#pragma once

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"

namespace hv {

// UV sphere: u = longitude / 2pi, v = colatitude / pi (v = 0 at the +Y pole).
Mesh makeSphere(float radius, int segments = 64, int rings = 32);
// Plane in XZ at y = 0 facing +Y; u along +X, v along +Z.
Mesh makePlane(float size_x, float size_z);
// Axis-aligned box; each face maps the full [0,1]^2 UV square.
Mesh makeBox(const glm::vec3& half_extents);
// Capsule along Y: a cylinder of height 2 * half_length capped by hemispheres of `radius`;
// v runs along the profile by arc length.
Mesh makeCapsule(float radius, float half_length, int segments = 48, int rings = 24);

// Appends `material`, `mesh` drawn with it, and an object placing the mesh at `position`
// (translation only); returns the object's index. For scenes built in code (tests, tools).
int addMeshObject(Scene& scene, Mesh mesh, const Material& material, const glm::vec3& position);

}  // namespace hv

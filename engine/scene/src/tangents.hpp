// Tangent generation for meshes that come without tangents (glTF files that omit TANGENT).
//
// MikkTSpace-compatible in its conventions, not a bit-exact port of Morten Mikkelsen's
// mikktspace.c (no Debian package exists): per triangle, the tangent and bitangent come from the
// UV derivatives; at each corner the tangent is projected into the vertex normal's plane and
// accumulated with the corner's angle as weight; per vertex the sum is Gram-Schmidt
// orthogonalised against the normal. Handedness w = -sign(dot(cross(N, T), dP/dv)), so that
// B = cross(N, T) * w points along -v: glTF's texture v runs down the image (origin top left),
// MikkTSpace works with v up (OpenGL), and a glTF normal map's green channel points up the image
// (glTF 2.0 spec, material.normalTexture; checked by NormalTangentTest in
// tests/render/test_gltf_render.cpp, whose normal-mapped cells match the real geometry only so).
// Triangles of opposite handedness (mirrored UVs) never share a vertex: a vertex used by both gets
// split. Differences from mikktspace.c: it also splits vertices across sharp tangent
// discontinuities and welds identical vertices first; this generator does neither, so results
// differ in such cases.
#pragma once

#include "halfvec/scene/scene.hpp"

namespace hv {

// Overwrites every vertex tangent of `mesh` (a triangle list with unit normals) using UV set
// `texcoord` (0 or 1). May append vertices (handedness splits) and rewrite indices.
void generateTangents(Mesh& mesh, int texcoord = 0);

}  // namespace hv

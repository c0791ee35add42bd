// CPU float cube map with a mip chain, in OpenGL's cube-map conventions so the GPU upload copies
// each face as-is: face order +X, -X, +Y, -Y, +Z, -Z (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face);
// texel (x, y) of a face has y = the row in memory (GL's t grows with y), and its center maps to
// (sc, tc) = (2 (x + 0.5) / size - 1, 2 (y + 0.5) / size - 1) and to the direction of the GL
// spec's table 8.19 (e.g. +X: (1, -tc, -sc)).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace hv {

struct CubeMapF {
  int size = 0;  // face size of mip 0
  // levels[mip][face]: size_m * size_m texels, size_m = max(size >> mip, 1).
  std::vector<std::array<std::vector<glm::vec3>, 6>> levels;

  int mipCount() const { return int(levels.size()); }
  int mipSize(int mip) const { return size >> mip > 0 ? size >> mip : 1; }
  glm::vec3& at(int mip, int face, int x, int y) {
    return levels[size_t(mip)][size_t(face)][size_t(y) * size_t(mipSize(mip)) + size_t(x)];
  }
  const glm::vec3& at(int mip, int face, int x, int y) const {
    return levels[size_t(mip)][size_t(face)][size_t(y) * size_t(mipSize(mip)) + size_t(x)];
  }
  // Bilinear within the face (clamped at face edges, no cross-face filtering).
  glm::vec3 sample(glm::vec3 dir, int mip) const;
  // Trilinear between mips; lod clamped to [0, mipCount() - 1].
  glm::vec3 sampleLod(glm::vec3 dir, float lod) const;
};

// An all-black cube of face size `size` with `mips` levels (mips <= 0: the full chain to 1x1).
CubeMapF makeCubeMap(int size, int mips = 1);

// Unit direction through (continuous) face coordinates u, v in [0, 1] of `face`.
glm::vec3 cubeDirection(int face, float u, float v);
// Direction of texel (x, y) center of a face of size `size`.
glm::vec3 cubeTexelDirection(int face, int x, int y, int size);
// Face and (u, v) in [0, 1] of a direction (need not be normalized).
int cubeFaceUV(glm::vec3 dir, float& u, float& v);
// Exact solid angle of texel (x, y) of a face of size `size` (sums to 4 pi over the cube).
float cubeTexelSolidAngle(int x, int y, int size);

// Fills mips 1.. of `cube` by 2x2 box filtering from the mip above (levels must exist).
void downsampleCubeMips(CubeMapF& cube);

}  // namespace hv

#include "halfvec/ibl/cubemap.hpp"

#include <algorithm>
#include <cmath>

namespace hv {

CubeMapF makeCubeMap(int size, int mips) {
  CubeMapF c;
  c.size = size;
  int full = 1;
  while ((size >> full) > 0) ++full;  // levels down to 1x1
  if (mips <= 0 || mips > full) mips = full;
  c.levels.resize(size_t(mips));
  for (int m = 0; m < mips; ++m)
    for (auto& face : c.levels[size_t(m)])
      face.assign(size_t(c.mipSize(m)) * size_t(c.mipSize(m)), glm::vec3(0.0f));
  return c;
}

glm::vec3 cubeDirection(int face, float u, float v) {
  const float sc = 2.0f * u - 1.0f, tc = 2.0f * v - 1.0f;
  glm::vec3 d;
  switch (face) {
    case 0:
      d = {1.0f, -tc, -sc};
      break;
    case 1:
      d = {-1.0f, -tc, sc};
      break;
    case 2:
      d = {sc, 1.0f, tc};
      break;
    case 3:
      d = {sc, -1.0f, -tc};
      break;
    case 4:
      d = {sc, -tc, 1.0f};
      break;
    default:
      d = {-sc, -tc, -1.0f};
      break;
  }
  return glm::normalize(d);
}

glm::vec3 cubeTexelDirection(int face, int x, int y, int size) {
  return cubeDirection(face, (float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
}

int cubeFaceUV(glm::vec3 d, float& u, float& v) {
  const glm::vec3 a = glm::abs(d);
  int face;
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x >= 0.0f ? 0 : 1;
    ma = a.x;
    sc = d.x >= 0.0f ? -d.z : d.z;
    tc = -d.y;
  } else if (a.y >= a.z) {
    face = d.y >= 0.0f ? 2 : 3;
    ma = a.y;
    sc = d.x;
    tc = d.y >= 0.0f ? d.z : -d.z;
  } else {
    face = d.z >= 0.0f ? 4 : 5;
    ma = a.z;
    sc = d.z >= 0.0f ? d.x : -d.x;
    tc = -d.y;
  }
  ma = std::max(ma, 1e-30f);
  u = 0.5f * (sc / ma + 1.0f);
  v = 0.5f * (tc / ma + 1.0f);
  return face;
}

float cubeTexelSolidAngle(int x, int y, int size) {
  // Solid angle of the face rectangle [0, x] x [0, y] on the plane at distance 1 (the integral of
  // (1 + x^2 + y^2)^(-3/2)), combined over the texel's four corners.
  auto area = [](double px, double py) {
    return std::atan2(px * py, std::sqrt(px * px + py * py + 1.0));
  };
  const double inv = 2.0 / double(size);
  const double x0 = x * inv - 1.0, x1 = (x + 1) * inv - 1.0;
  const double y0 = y * inv - 1.0, y1 = (y + 1) * inv - 1.0;
  return float(area(x0, y0) - area(x0, y1) - area(x1, y0) + area(x1, y1));
}

glm::vec3 CubeMapF::sample(glm::vec3 dir, int mip) const {
  float u, v;
  const int face = cubeFaceUV(dir, u, v);
  const int s = mipSize(mip);
  const float fx = u * float(s) - 0.5f, fy = v * float(s) - 0.5f;
  const float flx = std::floor(fx), fly = std::floor(fy);
  const float tx = fx - flx, ty = fy - fly;
  const int x0 = std::clamp(int(flx), 0, s - 1), x1 = std::clamp(int(flx) + 1, 0, s - 1);
  const int y0 = std::clamp(int(fly), 0, s - 1), y1 = std::clamp(int(fly) + 1, 0, s - 1);
  const glm::vec3 a = glm::mix(at(mip, face, x0, y0), at(mip, face, x1, y0), tx);
  const glm::vec3 b = glm::mix(at(mip, face, x0, y1), at(mip, face, x1, y1), tx);
  return glm::mix(a, b, ty);
}

glm::vec3 CubeMapF::sampleLod(glm::vec3 dir, float lod) const {
  lod = std::clamp(lod, 0.0f, float(mipCount() - 1));
  const int m0 = int(lod);
  const float t = lod - float(m0);
  if (t <= 0.0f || m0 + 1 >= mipCount()) return sample(dir, m0);
  return glm::mix(sample(dir, m0), sample(dir, m0 + 1), t);
}

void downsampleCubeMips(CubeMapF& cube) {
  for (int m = 1; m < cube.mipCount(); ++m) {
    const int s = cube.mipSize(m), ps = cube.mipSize(m - 1);
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x) {
          const int px = std::min(2 * x, ps - 1), py = std::min(2 * y, ps - 1);
          const int qx = std::min(2 * x + 1, ps - 1), qy = std::min(2 * y + 1, ps - 1);
          cube.at(m, f, x, y) = 0.25f * (cube.at(m - 1, f, px, py) + cube.at(m - 1, f, qx, py) +
                                         cube.at(m - 1, f, px, qy) + cube.at(m - 1, f, qx, qy));
        }
  }
}

}  // namespace hv

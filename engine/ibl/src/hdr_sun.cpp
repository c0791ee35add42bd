#include "halfvec/ibl/hdr_sun.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

#include <glm/gtc/constants.hpp>

#include "halfvec/ibl/ibl.hpp"

namespace hv {
namespace {

constexpr float kPi = glm::pi<float>();

// Solid angle of a texel of row y of a w x h equirect: (2 pi / w) (pi / h) sin(theta) at the row's
// center.
float texelSolidAngle(int y, int w, int h) {
  const float theta = kPi * (float(y) + 0.5f) / float(h);
  return (2.0f * kPi / float(w)) * (kPi / float(h)) * std::sin(theta);
}

glm::vec3 texelDirection(int x, int y, int w, int h) {
  return equirectDirection({(float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)});
}

// The 8 neighbours of texel i that exist (rows clamp at the poles, columns wrap).
template <class F>
void forNeighbours(int i, int w, int h, F&& f) {
  const int x = i % w, y = i / w;
  for (int dy = -1; dy <= 1; ++dy) {
    const int ny = y + dy;
    if (ny < 0 || ny >= h) continue;
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      f(ny * w + (x + dx + w) % w);
    }
  }
}

}  // namespace

HdrSun findHdrSun(const ImageRGBf& img) {
  HdrSun sun;
  const int w = img.width, h = img.height;
  if (w <= 0 || h <= 0 || img.px.size() != size_t(w) * size_t(h)) return sun;
  // The mean radiance over the sphere and the brightest texel.
  double power = 0.0;
  int peak = 0;
  for (int y = 0; y < h; ++y) {
    const float dw = texelSolidAngle(y, w, h);
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      const float l = luminance(img.px[size_t(i)]);
      if (!std::isfinite(l)) return sun;
      power += double(l) * dw;
      if (l > luminance(img.px[size_t(peak)])) peak = i;
    }
  }
  const float mean = float(power / (4.0 * double(kPi)));
  const float peak_lum = luminance(img.px[size_t(peak)]);
  if (!(peak_lum > 0.0f) || peak_lum < kHdrSunPeakOverMean * mean) return sun;
  // The texels connected to the peak that are within kHdrSunRegionFraction of it; stop as soon as
  // they cover more than a sun may.
  const float threshold = peak_lum / kHdrSunRegionFraction;
  std::vector<char> in(img.px.size(), 0);
  std::vector<int> todo{peak};
  in[size_t(peak)] = 1;
  float omega = 0.0f;
  while (!todo.empty()) {
    const int i = todo.back();
    todo.pop_back();
    sun.texels.push_back(i);
    omega += texelSolidAngle(i / w, w, h);
    if (omega > kHdrSunMaxSolidAngle) return HdrSun{};
    forNeighbours(i, w, h, [&](int n) {
      if (in[size_t(n)] || luminance(img.px[size_t(n)]) < threshold) return;
      in[size_t(n)] = 1;
      todo.push_back(n);
    });
  }
  std::sort(sun.texels.begin(), sun.texels.end());
  // The fill: the mean radiance of the texels bordering the sun (solid-angle weighted), the sky
  // around it.
  glm::dvec3 border(0.0);
  double border_w = 0.0;
  std::vector<char> seen = in;
  for (int i : sun.texels) {
    forNeighbours(i, w, h, [&](int n) {
      if (seen[size_t(n)]) return;
      seen[size_t(n)] = 1;
      const double dw = texelSolidAngle(n / w, w, h);
      border += glm::dvec3(img.px[size_t(n)]) * dw;
      border_w += dw;
    });
  }
  sun.fill = border_w > 0.0 ? glm::vec3(border / border_w) : glm::vec3(0.0f);
  // What the texels hold above the fill is the light: its illuminance at normal incidence and
  // the direction of its centroid.
  glm::dvec3 e(0.0), dir(0.0);
  for (int i : sun.texels) {
    const float dw = texelSolidAngle(i / w, w, h);
    const glm::vec3 excess = glm::max(img.px[size_t(i)] - sun.fill, glm::vec3(0.0f));
    e += glm::dvec3(excess) * double(dw);
    dir += glm::dvec3(texelDirection(i % w, i / w, w, h)) * double(luminance(excess) * dw);
  }
  if (!(glm::length(dir) > 0.0)) return HdrSun{};
  sun.found = true;
  sun.direction = glm::vec3(glm::normalize(dir));
  sun.illuminance = glm::vec3(e);
  sun.solid_angle = omega;
  return sun;
}

void removeHdrSun(ImageRGBf& img, const HdrSun& sun) {
  if (!sun.found) return;
  // min, not the fill itself: a channel below the fill keeps its value, so the image loses
  // exactly the light's illuminance (the excess above the fill).
  for (int i : sun.texels) img.px[size_t(i)] = glm::min(img.px[size_t(i)], sun.fill);
}

const HdrSun& hdrSunOf(const Environment& env) {
  static const HdrSun none;
  if (env.kind != EnvironmentKind::HdrFile) return none;
  const std::string key = hdrFileIdentity(env.path);
  if (key.empty()) return none;
  static std::mutex mutex;
  static std::map<std::string, HdrSun> found;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = found.find(key);
  if (it != found.end()) return it->second;
  HdrSun sun;
  try {
    sun = findHdrSun(loadHdr(env.path));
  } catch (const IblError&) {
    sun = HdrSun{};  // the bake names the file and the problem
  }
  return found.emplace(key, std::move(sun)).first->second;
}

Light hdrSunLight(const Environment& env, const HdrSun& sun) {
  const float e = luminance(sun.illuminance);
  Light l;
  l.type = LightType::Directional;
  l.direction = -environmentToWorld(env, sun.direction);
  l.color = e > 0.0f ? sun.illuminance / e : glm::vec3(1.0f);
  l.intensity = e * env.intensity;
  // The disk of the same solid angle: 2 pi (1 - cos r) = omega.
  const float cos_r = std::clamp(1.0f - sun.solid_angle / (2.0f * kPi), -1.0f, 1.0f);
  l.angular_diameter = std::min(2.0f * std::acos(cos_r), kMaxAngularDiameter);
  return l;
}

}  // namespace hv

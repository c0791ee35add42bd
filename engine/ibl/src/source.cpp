// Environment sources: Radiance .hdr files, the procedural sky, a uniform color; -> cube map.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <glm/gtc/constants.hpp>

#include "halfvec/core/input_file.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/ibl/hdr_sun.hpp"
#include "halfvec/core/parallel.hpp"

namespace hv {
namespace {

constexpr float kPi = glm::pi<float>();

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw IblError("HDR '" + path + "': " + what);
}

// Radiance RGBE -> float as Bruce Walter's rgbe.c and stb_image do: mantissa * 2^(e - 136), 0 for
// e = 0 (Radiance's own colr_color adds half a mantissa step; the engine keeps the common
// convention, so images decode as before).
glm::vec3 rgbeToFloat(const uint8_t* c) {
  if (c[3] == 0) return glm::vec3(0.0f);
  const float f = std::ldexp(1.0f, int(c[3]) - (128 + 8));
  return glm::vec3(float(c[0]) * f, float(c[1]) * f, float(c[2]) * f);
}

// Decodes the raster of a w x h RGBE file scanline by scanline, as Radiance's freadcolrs does
// (Ward, "Real Pixels", Graphics Gems II, 1991; Radiance src/common/color.c): a scanline of width
// 8..32767 starting with the bytes 2, 2, w >> 8 (< 128), w & 255 is run-length encoded per
// component (a count byte > 128 is a run of count - 128 copies of the next byte, else count
// literal bytes); any other scanline is flat, 4 bytes per pixel, where a pixel (1, 1, 1, n)
// repeats the previous pixel n << shift times (the pre-1991 encoding; shift grows by 8 for each
// consecutive repeat pixel). Encodings may change from one scanline to the next. Every byte read
// is checked against the end of the data and every run against the scanline's end.
void decodeRgbe(const std::string& path, const uint8_t* b, size_t size, size_t pos, int w, int h,
                ImageRGBf& img) {
  std::vector<uint8_t> line(size_t(w) * 4);
  for (int y = 0; y < h; ++y) {
    const auto truncated = [&] {
      fail(path, "truncated (data ends in scanline " + std::to_string(y) + " of " +
                     std::to_string(h) + ")");
    };
    const auto corrupt = [&](const char* why) {
      fail(path, "corrupt scanline " + std::to_string(y) + " (" + why + ")");
    };
    if (size - pos < 4) truncated();
    const bool rle = w >= 8 && w < 32768 && b[pos] == 2 && b[pos + 1] == 2 && !(b[pos + 2] & 0x80);
    if (rle) {
      if (((int(b[pos + 2]) << 8) | b[pos + 3]) != w) corrupt("RLE length mismatch");
      pos += 4;
      for (int c = 0; c < 4; ++c) {
        int x = 0;
        while (x < w) {
          if (pos >= size) truncated();
          int count = b[pos++];
          if (count > 128) {  // a run of count - 128 copies of the next byte
            count -= 128;
            if (x + count > w) corrupt("RLE run past the end of the scanline");
            if (pos >= size) truncated();
            for (int k = 0; k < count; ++k) line[size_t(x + k) * 4 + size_t(c)] = b[pos];
            ++pos;
          } else {  // count literal bytes
            if (x + count > w) corrupt("RLE literal past the end of the scanline");
            if (size - pos < size_t(count)) truncated();
            for (int k = 0; k < count; ++k)
              line[size_t(x + k) * 4 + size_t(c)] = b[pos + size_t(k)];
            pos += size_t(count);
          }
          x += count;
        }
      }
    } else {
      int x = 0, shift = 0;
      while (x < w) {
        if (size - pos < 4) truncated();
        const uint8_t* px = b + pos;
        pos += 4;
        if (px[0] == 1 && px[1] == 1 && px[2] == 1) {  // old-style run of the previous pixel
          if (x == 0) corrupt("run-length pixel without a previous pixel");
          if (shift > 16) corrupt("run-length count overflows");
          const int64_t count = int64_t(px[3]) << shift;
          if (count > w - x) corrupt("run past the end of the scanline");
          for (int64_t k = 0; k < count; ++k, ++x) {
            std::memcpy(&line[size_t(x) * 4], &line[size_t(x - 1) * 4], 4);
          }
          shift += 8;
        } else {
          std::memcpy(&line[size_t(x) * 4], px, 4);
          ++x;
          shift = 0;
        }
      }
    }
    for (int x = 0; x < w; ++x) img.at(x, y) = rgbeToFloat(&line[size_t(x) * 4]);
  }
}

// The fewest bytes one scanline of width w can take in any encoding decodeRgbe accepts: one
// pixel plus old-style repeat pixels (each covers up to 255 << shift), or the RLE header plus one
// 2-byte run per 127 values of each component.
size_t minScanlineBytes(int w) {
  size_t old_style = 4;
  for (int64_t covered = 1, shift = 0; covered < w; shift += 8) {
    covered += int64_t(255) << shift;
    old_style += 4;
  }
  if (w < 8 || w >= 32768) return old_style;
  return std::min(old_style, 4 + 4 * 2 * size_t((w + 126) / 127));
}

}  // namespace

float luminance(glm::vec3 c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

std::string hdrFileIdentity(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p = fs::absolute(path, ec);
  const auto size = fs::file_size(p, ec);
  if (ec) return {};
  const auto mtime = fs::last_write_time(p, ec).time_since_epoch().count();
  if (ec) return {};
  return p.string() + "|" + std::to_string(size) + "|" + std::to_string(mtime);
}

ImageRGBf decodeHdr(const uint8_t* b, size_t size, const std::string& path, int max_width) {
  size_t pos = 0;
  auto line = [&]() -> std::string {
    std::string s;
    while (pos < size && b[pos] != '\n' && s.size() < 4096) s.push_back(char(b[pos++]));
    if (pos >= size) fail(path, "truncated header");
    ++pos;
    return s;
  };
  if (size < 2 || b[0] != '#' || b[1] != '?')
    fail(path, "not a Radiance RGBE file (missing '#?RADIANCE' / '#?RGBE' signature)");
  const std::string magic = line();
  if (magic != "#?RADIANCE" && magic != "#?RGBE")
    fail(path, "not a Radiance RGBE file (signature '" + magic.substr(0, 32) + "')");
  bool format_ok = false;
  for (std::string l = line(); !l.empty(); l = line()) {
    if (l.rfind("FORMAT=", 0) == 0) {
      if (l != "FORMAT=32-bit_rle_rgbe")
        fail(path, "unsupported " + l.substr(0, 64) + " (only FORMAT=32-bit_rle_rgbe)");
      format_ok = true;
    }
  }
  if (!format_ok) fail(path, "bad header (no FORMAT=32-bit_rle_rgbe line)");
  const std::string res = line();
  long h = 0, w = 0;
  char tail = 0;
  if (std::sscanf(res.c_str(), "-Y %ld +X %ld%c", &h, &w, &tail) != 2)
    fail(path, "unsupported resolution line '" + res.substr(0, 64) + "' (need '-Y H +X W')");
  if (w <= 0 || h <= 0 || w > max_width || h > max_width / 2) {
    fail(path, "dimensions " + std::to_string(w) + "x" + std::to_string(h) + " outside 1.." +
                   std::to_string(max_width) + " x 1.." + std::to_string(max_width / 2) +
                   " (kMaxHdrWidth)");
  }
  if (w != 2 * h)
    fail(path, "not equirectangular (" + std::to_string(w) + "x" + std::to_string(h) +
                   ", need a 2:1 aspect)");
  // Before allocating: the data must be able to hold the declared size.
  const size_t need = size_t(h) * minScanlineBytes(int(w));
  if (size - pos < need) {
    fail(path, "truncated: " + std::to_string(size - pos) + " bytes of pixel data cannot hold " +
                   std::to_string(w) + "x" + std::to_string(h) + " pixels (at least " +
                   std::to_string(need) + " needed)");
  }
  ImageRGBf img = makeImageRGBf(int(w), int(h));
  decodeRgbe(path, b, size, pos, int(w), int(h), img);
  return img;
}

ImageRGBf loadHdr(const std::string& path) {
  // The largest file of the largest image: flat scanlines, 4 bytes per pixel, plus a header.
  const uint64_t max_size = uint64_t(kMaxHdrWidth) * uint64_t(kMaxHdrWidth / 2) * 4 + (1 << 20);
  std::string b;
  try {
    b = readInputFile(path, max_size, "the largest file a kMaxHdrWidth-wide image needs");
  } catch (const InputError& e) {
    fail(path, e.reason);
  }
  return decodeHdr(reinterpret_cast<const uint8_t*>(b.data()), b.size(), path);
}

glm::vec2 equirectUV(glm::vec3 d) {
  d = glm::normalize(d);
  return {std::atan2(d.x, -d.z) / (2.0f * kPi) + 0.5f,
          std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi};
}

glm::vec3 equirectDirection(glm::vec2 uv) {
  const float phi = (uv.x - 0.5f) * 2.0f * kPi, theta = uv.y * kPi;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

glm::vec3 skySunDirection(const SkyParams& s) {
  const float el = glm::radians(s.sun_elevation_deg), az = glm::radians(s.sun_azimuth_deg);
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

namespace {
// The dome: horizon -> zenith blend by a (1 - cos theta)^4 weight on the horizon, i.e. a bright
// band near the horizon.
glm::vec3 skyDome(const SkyParams& s, float mu) {
  const float t = std::pow(1.0f - std::clamp(mu, 0.0f, 1.0f), 4.0f);
  return glm::mix(s.zenith, s.horizon, t);
}
}  // namespace

// E_sky = int L cos over the upper hemisphere = 2 pi int_0^1 L(mu) mu dmu, by a 64-step midpoint
// rule (exact enough for a smooth quartic blend).
float skyDomeIlluminance(const SkyParams& s) {
  float e = 0.0f;
  for (int i = 0; i < 64; ++i) {
    const float mu = (float(i) + 0.5f) / 64.0f;
    e += luminance(skyDome(s, mu)) * mu / 64.0f;
  }
  return 2.0f * kPi * e;
}

glm::vec3 skyRadiance(const SkyParams& s, glm::vec3 dir) {
  return skyRadiance(s, dir, skyDomeIlluminance(s));
}

glm::vec3 skyRadiance(const SkyParams& s, glm::vec3 dir, float e_sky) {
  dir = glm::normalize(dir);
  auto dome = [&](float mu) { return skyDome(s, mu); };
  const glm::vec3 sun_dir = skySunDirection(s);
  const float cos_r = std::cos(glm::radians(s.sun_angular_radius_deg));
  const float sun_omega = 2.0f * kPi * (1.0f - cos_r);
  const bool in_sun = s.sun_disk && glm::dot(dir, sun_dir) >= cos_r;
  if (!in_sun && dir.y >= 0.0f) return dome(dir.y);
  const float e_sun = s.sun_to_sky * e_sky;  // normal illuminance of the sun
  const glm::vec3 sun_chroma = s.sun_color / std::max(luminance(s.sun_color), 1e-6f);
  if (in_sun) return sun_chroma * (e_sun / sun_omega);
  // Ground: Lambertian, lit by the sky dome (its horizontal illuminance, colored like its mean)
  // and the sun at its elevation.
  const glm::vec3 sky_mean = 0.5f * (s.zenith + s.horizon);
  const glm::vec3 e = sky_mean / std::max(luminance(sky_mean), 1e-6f) * e_sky +
                      sun_chroma * e_sun * std::max(sun_dir.y, 0.0f);
  return s.ground_albedo / kPi * e;
}

glm::vec3 environmentToWorld(const Environment& env, glm::vec3 d) {
  const float a = glm::radians(env.rotation_deg), c = std::cos(a), sn = std::sin(a);
  return glm::normalize(glm::vec3(c * d.x + sn * d.z, d.y, -sn * d.x + c * d.z));
}

glm::vec3 skySunWorldDirection(const Environment& env, const SkyParams& sky) {
  return environmentToWorld(env, skySunDirection(sky));
}

Light skySunLight(const Environment& env, const SkyParams& sky) {
  const float cos_r = std::cos(glm::radians(sky.sun_angular_radius_deg));
  const float sin_r = std::sin(glm::radians(sky.sun_angular_radius_deg));
  // The disk's radiance as skyRadiance has it, and the illuminance a disk of that radiance and
  // half-angle r gives at normal incidence: L pi sin^2 r (the projected solid angle).
  const float e_sun = sky.sun_to_sky * skyDomeIlluminance(sky);
  const float radiance = e_sun / (2.0f * kPi * (1.0f - cos_r));
  Light l;
  l.type = LightType::Directional;
  l.direction = -skySunWorldDirection(env, sky);
  l.color = sky.sun_color / std::max(luminance(sky.sun_color), 1e-6f);
  l.intensity = radiance * kPi * sin_r * sin_r * env.intensity;
  l.angular_diameter =
      std::min(2.0f * glm::radians(sky.sun_angular_radius_deg), kMaxAngularDiameter);
  return l;
}

glm::vec3 EnvSource::radiance(glm::vec3 dir) const {
  // Rotating the environment by +theta about +Y = looking up the unrotated one at -theta.
  const float a = glm::radians(rotation_deg), c = std::cos(a), s = std::sin(a);
  const glm::vec3 d(c * dir.x - s * dir.z, dir.y, s * dir.x + c * dir.z);
  switch (kind) {
    case EnvironmentKind::Uniform:
      return color * intensity;
    case EnvironmentKind::Sky:
      // A source built by hand (not makeEnvSource) has no cached dome illuminance yet.
      return skyRadiance(sky, d,
                         sky_illuminance > 0.0f ? sky_illuminance : skyDomeIlluminance(sky)) *
             intensity;
    case EnvironmentKind::HdrFile: {
      const glm::vec2 uv = equirectUV(d);
      const int w = equirect.width, h = equirect.height;
      const float fx = uv.x * float(w) - 0.5f, fy = uv.y * float(h) - 0.5f;
      const float flx = std::floor(fx), fly = std::floor(fy);
      const float tx = fx - flx, ty = fy - fly;
      const int x0 = ((int(flx) % w) + w) % w, x1 = (x0 + 1) % w;  // wraps in longitude
      const int y0 = std::clamp(int(fly), 0, h - 1), y1 = std::clamp(int(fly) + 1, 0, h - 1);
      const glm::vec3 top = glm::mix(equirect.at(x0, y0), equirect.at(x1, y0), tx);
      const glm::vec3 bot = glm::mix(equirect.at(x0, y1), equirect.at(x1, y1), tx);
      return glm::mix(top, bot, ty) * intensity;
    }
    case EnvironmentKind::None:
      break;
  }
  return glm::vec3(0.0f);
}

EnvSource makeEnvSource(const Environment& env, const SkyParams& sky) {
  EnvSource src;
  src.kind = env.kind;
  src.color = env.color;
  src.sky = sky;
  src.sky_illuminance = skyDomeIlluminance(sky);
  src.intensity = env.intensity;
  src.rotation_deg = env.rotation_deg;
  if (env.kind == EnvironmentKind::None)
    throw IblError("environment kind None has nothing to bake");
  if (env.kind == EnvironmentKind::HdrFile) {
    src.equirect = loadHdr(env.path);
    // Where the HDR's sun is drawn as a light (skySunIsLight), the environment goes without it.
    if (!sky.sun_disk) removeHdrSun(src.equirect, findHdrSun(src.equirect));
  }
  return src;
}

CubeMapF envToCube(const EnvSource& src, int size, int supersample, int threads) {
  if (size <= 0) throw IblError("envToCube: cube size " + std::to_string(size) + " <= 0");
  CubeMapF cube = makeCubeMap(size, 1);
  const int ss = std::max(supersample, 1);
  detail::parallelFor(6 * size, threads, [&](int row) {
    const int face = row / size, y = row % size;
    for (int x = 0; x < size; ++x) {
      glm::vec3 sum(0.0f);
      for (int j = 0; j < ss; ++j)
        for (int i = 0; i < ss; ++i) {
          const float u = (float(x) + (float(i) + 0.5f) / float(ss)) / float(size);
          const float v = (float(y) + (float(j) + 0.5f) / float(ss)) / float(size);
          sum += src.radiance(cubeDirection(face, u, v));
        }
      cube.at(0, face, x, y) = sum / float(ss * ss);
    }
  });
  return cube;
}

}  // namespace hv

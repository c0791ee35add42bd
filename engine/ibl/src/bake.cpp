// bakeEnvironment: source -> cube -> prefiltered mips, env BRDF, SH9, irradiance; disk cache.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/constants.hpp>

#include "halfvec/ibl/ibl.hpp"
#include "halfvec/ibl/ibl_math.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/core/parallel.hpp"

namespace fs = std::filesystem;

namespace hv {
namespace {

constexpr float kPi = glm::pi<float>();
constexpr uint32_t kCacheVersion = 2;  // bump when the bake's math or the file layout changes
constexpr char kCacheMagic[8] = {'H', 'V', 'I', 'B', 'L', 'C', 'H', '\n'};

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// SH9 basis of ibl.glsl (Ramamoorthi & Hanrahan 2001 eq. 3).
std::array<float, 9> shBasis(glm::vec3 d) {
  return {0.282095f,
          0.488603f * d.y,
          0.488603f * d.z,
          0.488603f * d.x,
          1.092548f * d.x * d.y,
          1.092548f * d.y * d.z,
          0.315392f * (3.0f * d.z * d.z - 1.0f),
          1.092548f * d.x * d.z,
          0.546274f * (d.x * d.x - d.y * d.y)};
}

// 64-bit FNV-1a.
uint64_t fnv1a(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

void writeCube(std::ostream& o, const CubeMapF& c) {
  const int32_t hdr[2] = {c.size, c.mipCount()};
  o.write(reinterpret_cast<const char*>(hdr), sizeof(hdr));
  for (const auto& level : c.levels)
    for (const auto& face : level)
      o.write(reinterpret_cast<const char*>(face.data()),
              std::streamsize(face.size() * sizeof(glm::vec3)));
}

bool readCube(std::istream& in, CubeMapF& c) {
  int32_t hdr[2] = {0, 0};
  if (!in.read(reinterpret_cast<char*>(hdr), sizeof(hdr))) return false;
  if (hdr[0] < 0 || hdr[0] > 16384 || hdr[1] < 0 || hdr[1] > 16) return false;
  if (hdr[0] == 0) {
    c = CubeMapF{};
    return true;
  }
  c = makeCubeMap(hdr[0], std::max(hdr[1], 1));
  if (c.mipCount() != hdr[1]) return false;
  for (auto& level : c.levels)
    for (auto& face : level)
      if (!in.read(reinterpret_cast<char*>(face.data()),
                   std::streamsize(face.size() * sizeof(glm::vec3))))
        return false;
  return true;
}

void writeCache(const fs::path& path, const IblBake& b) {
  fs::create_directories(path.parent_path());
  // Written to a temporary file of its own beside the cache file and renamed over it when whole
  // (atomic: a concurrent reader sees the old file or the whole new one); the temporary is removed
  // if the write fails or a signal ends the run.
  OutputFiles out;
  const fs::path tmp = out.add(path);
  {
    std::ofstream o(tmp, std::ios::binary);
    if (!o) throw IblError("IBL cache '" + tmp.string() + "': cannot open for writing");
    o.write(kCacheMagic, sizeof(kCacheMagic));
    o.write(reinterpret_cast<const char*>(&kCacheVersion), sizeof(kCacheVersion));
    writeCube(o, b.radiance);
    const int32_t n = b.env_brdf_size;
    o.write(reinterpret_cast<const char*>(&n), sizeof(n));
    o.write(reinterpret_cast<const char*>(b.env_brdf.data()),
            std::streamsize(b.env_brdf.size() * sizeof(glm::vec2)));
    o.write(reinterpret_cast<const char*>(b.sh.data()), sizeof(b.sh));
    writeCube(o, b.irradiance);
    if (!o) throw IblError("IBL cache '" + tmp.string() + "': write failed");
  }
  out.commit();
}

bool readCache(const fs::path& path, IblBake& b) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  char magic[8];
  uint32_t version = 0;
  if (!in.read(magic, 8) || std::memcmp(magic, kCacheMagic, 8) != 0) return false;
  if (!in.read(reinterpret_cast<char*>(&version), 4) || version != kCacheVersion) return false;
  if (!readCube(in, b.radiance)) return false;
  int32_t n = 0;
  if (!in.read(reinterpret_cast<char*>(&n), 4) || n < 0 || n > 4096) return false;
  b.env_brdf_size = n;
  b.env_brdf.resize(size_t(n) * size_t(n));
  if (!in.read(reinterpret_cast<char*>(b.env_brdf.data()),
               std::streamsize(b.env_brdf.size() * sizeof(glm::vec2))))
    return false;
  if (!in.read(reinterpret_cast<char*>(b.sh.data()), sizeof(b.sh))) return false;
  if (!readCube(in, b.irradiance)) return false;
  in.peek();
  return in.eof();  // trailing bytes = not our file
}

std::string vecKey(glm::vec3 v) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%a,%a,%a", double(v.x), double(v.y), double(v.z));
  return buf;
}

}  // namespace

std::array<glm::vec3, 9> projectSH9(const CubeMapF& cube) {
  // L_lm = integral L(w) Y_lm(w) dw, as a sum over the texels of mip 0 weighted by their exact
  // solid angle (sums to 4 pi, so a constant is projected exactly).
  std::array<glm::dvec3, 9> acc{};
  const int s = cube.mipSize(0);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x) {
        const glm::vec3 d = cubeTexelDirection(f, x, y, s);
        const double w = cubeTexelSolidAngle(x, y, s);
        const std::array<float, 9> Y = shBasis(d);
        const glm::dvec3 L = glm::dvec3(cube.at(0, f, x, y)) * w;
        for (int i = 0; i < 9; ++i) acc[size_t(i)] += L * double(Y[size_t(i)]);
      }
  std::array<glm::vec3, 9> sh;
  for (int i = 0; i < 9; ++i) sh[size_t(i)] = glm::vec3(acc[size_t(i)]);
  return sh;
}

CubeMapF irradianceCube(const CubeMapF& cube, int size, int threads) {
  // E(n) = integral L(w) max(n.w, 0) dw by brute force over the texels of the source mip of face
  // size <= max(size, 16), each weighted by its exact solid angle (a constant L gives pi L up to
  // the discretization of the clamped cosine, ~1e-4 relative at 16x16).
  int m = 0;
  while (m + 1 < cube.mipCount() && cube.mipSize(m) > std::max(size, 16)) ++m;
  const int ss = cube.mipSize(m);
  struct Texel {
    glm::vec3 dir;
    glm::vec3 l_omega;
  };
  std::vector<Texel> src;
  src.reserve(size_t(6 * ss * ss));
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < ss; ++y)
      for (int x = 0; x < ss; ++x)
        src.push_back(
            {cubeTexelDirection(f, x, y, ss), cube.at(m, f, x, y) * cubeTexelSolidAngle(x, y, ss)});
  CubeMapF out = makeCubeMap(size, 1);
  detail::parallelFor(6 * size, threads, [&](int row) {
    const int face = row / size, y = row % size;
    for (int x = 0; x < size; ++x) {
      const glm::vec3 n = cubeTexelDirection(face, x, y, size);
      glm::dvec3 e(0.0);
      for (const Texel& t : src) {
        const float c = glm::dot(n, t.dir);
        if (c > 0.0f) e += glm::dvec3(t.l_omega * c);
      }
      out.at(0, face, x, y) = glm::vec3(e);
    }
  });
  return out;
}

std::string iblCacheDir(const BakeOptions& opt) {
  if (!opt.cache_dir.empty()) return opt.cache_dir;
  if (const char* d = std::getenv("HV_CACHE_DIR"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d)
    return (fs::path(d) / "halfvec").string();
  if (const char* d = std::getenv("HOME"); d && *d)
    return (fs::path(d) / ".cache" / "halfvec").string();
  return (fs::temp_directory_path() / "halfvec-cache").string();
}

namespace {

// The bake's sizes: the options' where set, else the environment's.
struct BakeSizes {
  int cube = 0;         // face size of mip 0
  int samples = 0;      // prefilter samples per texel
  int supersample = 0;  // per axis, for envToCube
};

BakeSizes bakeSizes(const Environment& env, const BakeOptions& opt) {
  BakeSizes n;
  n.cube = opt.cube_size > 0 ? opt.cube_size : env.cube_size;
  n.samples = opt.prefilter_samples > 0 ? opt.prefilter_samples : env.prefilter_samples;
  if (n.cube < 1 || n.cube > 8192 || (n.cube & (n.cube - 1)) != 0)
    throw IblError("bakeEnvironment: cube size " + std::to_string(n.cube) +
                   " is not a power of two in [1, 8192]");
  if (env.kind == EnvironmentKind::None) throw IblError("bakeEnvironment: environment kind None");
  n.supersample =
      env.kind == EnvironmentKind::HdrFile ? opt.supersample : std::max(opt.supersample, 4);
  return n;
}

// The cache file: its name is a hash of everything the result depends on. For a file: its
// absolute path, size and modification time (cheap; a rewritten file gets a new mtime).
fs::path cachePath(const Environment& env, const BakeOptions& opt, const BakeSizes& n) {
  std::ostringstream key;
  key << "v" << kCacheVersion << "|kind" << int(env.kind) << "|c" << vecKey(env.color) << "|i"
      << vecKey(glm::vec3(env.intensity, env.rotation_deg, 0.0f)) << "|n" << n.cube << ","
      << n.samples << "," << opt.min_mip_size << "," << n.supersample << "," << opt.env_brdf_size
      << "," << opt.env_brdf_samples << "," << opt.irradiance_size << "|v" << int(opt.brdf.v);
  if (env.kind == EnvironmentKind::Sky) {
    const SkyParams& s = opt.sky;
    key << "|sky" << vecKey(s.zenith) << vecKey(s.horizon) << vecKey(s.sun_color)
        << vecKey(glm::vec3(s.sun_elevation_deg, s.sun_azimuth_deg, s.sun_angular_radius_deg))
        << vecKey(glm::vec3(s.sun_to_sky, s.ground_albedo, 0.0f)) << (s.sun_disk ? "" : "|nosun");
  }
  if (env.kind == EnvironmentKind::HdrFile) {
    const std::string file = hdrFileIdentity(env.path);
    if (file.empty()) throw IblError("HDR '" + env.path + "': cannot open (missing file?)");
    key << "|file" << file << (opt.sky.sun_disk ? "" : "|nosun");
  }
  char name[64];
  std::snprintf(name, sizeof(name), "ibl-%016llx.bin", (unsigned long long)fnv1a(key.str()));
  return fs::path(iblCacheDir(opt)) / name;
}

// The bake proper, each stage timed: the source, its cube with the full mip chain (for filtered
// importance sampling), the prefiltered radiance, the env BRDF table, SH9, the irradiance cube.
void bakeStages(const Environment& env, const BakeOptions& opt, const BakeSizes& n, IblBake& bake) {
  BakeTimings& t = bake.timings;
  auto t0 = Clock::now();
  const EnvSource src = makeEnvSource(env, opt.sky);
  t.load_ms = msSince(t0);

  t0 = Clock::now();
  if (opt.progress)
    std::fprintf(stderr, "[ibl] source -> cube %dx%d (%dx%d supersampling)\n", n.cube, n.cube,
                 n.supersample, n.supersample);
  CubeMapF source = makeCubeMap(n.cube, 0);
  source.levels[0] = std::move(envToCube(src, n.cube, n.supersample, opt.threads).levels[0]);
  downsampleCubeMips(source);
  t.convert_ms = msSince(t0);

  t0 = Clock::now();
  bake.radiance = prefilterRadiance(source, n.samples, opt.min_mip_size, opt.threads, opt.progress);
  t.prefilter_ms = msSince(t0);

  t0 = Clock::now();
  if (opt.progress)
    std::fprintf(stderr, "[ibl] env BRDF table %dx%d (%d samples)\n", opt.env_brdf_size,
                 opt.env_brdf_size, opt.env_brdf_samples);
  bake.env_brdf_size = opt.env_brdf_size;
  bake.env_brdf = integrateEnvBrdf(opt.env_brdf_size, opt.env_brdf_samples, opt.threads, opt.brdf);
  t.env_brdf_ms = msSince(t0);

  t0 = Clock::now();
  bake.sh = projectSH9(source);
  t.sh_ms = msSince(t0);

  t0 = Clock::now();
  if (opt.irradiance_size > 0)
    bake.irradiance = irradianceCube(source, opt.irradiance_size, opt.threads);
  t.irradiance_ms = msSince(t0);
}

void printTimings(const BakeTimings& t) {
  std::fprintf(stderr,
               "[ibl] baked in %.0f ms (load %.0f, convert %.0f, prefilter %.0f, env BRDF %.0f, "
               "SH %.0f, irradiance %.0f, cache write %.0f)\n",
               t.total_ms, t.load_ms, t.convert_ms, t.prefilter_ms, t.env_brdf_ms, t.sh_ms,
               t.irradiance_ms, t.cache_ms);
}

}  // namespace

IblBake bakeEnvironment(const Environment& env, const BakeOptions& opt) {
  const auto t_total = Clock::now();
  const BakeSizes n = bakeSizes(env, opt);
  const fs::path cache_path = cachePath(env, opt, n);

  IblBake bake;
  BakeTimings& t = bake.timings;
  if (opt.use_cache) {
    const auto t0 = Clock::now();
    if (readCache(cache_path, bake)) {
      t.cache_ms = msSince(t0);
      t.cache_hit = true;
      t.total_ms = msSince(t_total);
      if (opt.progress)
        std::fprintf(stderr, "[ibl] cache hit %s (%.1f ms)\n", cache_path.c_str(), t.cache_ms);
      return bake;
    }
  }
  bakeStages(env, opt, n, bake);
  if (opt.use_cache) {
    const auto t0 = Clock::now();
    try {
      writeCache(cache_path, bake);
    } catch (const std::exception& e) {  // a read-only cache must not stop rendering
      std::fprintf(stderr, "[ibl] warning: cache not written: %s\n", e.what());
    }
    t.cache_ms = msSince(t0);
  }
  t.total_ms = msSince(t_total);
  if (opt.progress) printTimings(t);
  return bake;
}

}  // namespace hv

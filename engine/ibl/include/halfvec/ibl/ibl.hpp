// CPU bake of image-based lighting (Karis 2013, "Real Shading in Unreal Engine 4", section
// "Image-Based Lighting"): environment source -> cube map -> prefiltered radiance mips (split-sum
// first sum), env BRDF table (second sum), SH9 and cube-map irradiance; cached on disk. No GL:
// the upload lives in engine/render.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/ibl/cubemap.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/scene/scene.hpp"
#include "halfvec/shading/brdf.hpp"

namespace hv {

// Every failure of the IBL module: the message names the file and what is wrong.
class IblError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Procedural clear sky (EnvironmentKind::Sky). Units: relative radiance, 1.0 = a bright clear-sky
// horizon (think ~10 kcd/m^2 before Environment::intensity). Physically plausible ratios:
//  - sky dome: gradient from horizon (0.80, 0.85, 0.90) to zenith (0.25, 0.40, 0.80), i.e. the
//    horizon ~2x as bright as the zenith, as in the CIE clear sky;
//  - sun: a disc of angular radius 0.2666 deg (the real sun, solid angle 6.8e-5 sr) whose normal
//    illuminance is sun_to_sky times the dome's horizontal illuminance (clear day: direct ~5x
//    diffuse, e.g. 100 klux vs 20 klux); its radiance is illuminance / solid angle;
//  - ground (below the horizon): Lambertian albedo ground_albedo lit by sky + sun.
struct SkyParams {
  glm::vec3 zenith{0.25f, 0.40f, 0.80f};
  glm::vec3 horizon{0.80f, 0.85f, 0.90f};
  glm::vec3 sun_color{1.0f, 0.95f, 0.85f};  // chromaticity, luminance normalized away
  float sun_elevation_deg = 35.0f;
  float sun_azimuth_deg = 30.0f;  // from +Z towards +X
  float sun_angular_radius_deg = 0.2666f;
  float sun_to_sky = 5.0f;  // E_sun,normal / E_sky,horizontal
  float ground_albedo = 0.2f;
  // false: the sun's disk is left out of the sky (the dome shows there), because it is drawn as
  // a directional light instead (RenderSettings::sky_sun, skySunLight); the ground it lights
  // stays.
  bool sun_disk = true;
};

// Radiance of an environment in a world direction, before intensity / rotation.
struct EnvSource {
  EnvironmentKind kind = EnvironmentKind::Uniform;
  glm::vec3 color{1.0f};  // Uniform
  SkyParams sky;
  ImageRGBf equirect;  // HdrFile: linear radiance, row 0 = top (+Y)
  float intensity = 1.0f;
  float rotation_deg = 0.0f;  // about +Y, applied to the environment
  float sky_illuminance =
      0.0f;  // Sky: skyDomeIlluminance(sky), cached by makeEnvSource; 0 = compute per call
  glm::vec3 radiance(glm::vec3 dir) const;
};

// Horizontal illuminance of the procedural sky's dome (sun excluded).
float skyDomeIlluminance(const SkyParams& sky);
// Radiance of the procedural sky (see SkyParams) in direction `dir` (normalized inside).
// `dome_illuminance` = skyDomeIlluminance(sky) (pass it when evaluating many directions).
glm::vec3 skyRadiance(const SkyParams& sky, glm::vec3 dir, float dome_illuminance);
glm::vec3 skyRadiance(const SkyParams& sky, glm::vec3 dir);
glm::vec3 skySunDirection(const SkyParams& sky);
// A direction of the environment's own frame (the sky's, the equirect's) in the world: turned by
// the environment's rotation_deg about +Y (EnvSource::radiance looks the unrotated environment up
// at R(-rotation) dir).
glm::vec3 environmentToWorld(const Environment& env, glm::vec3 d);
// The direction towards the sun in the world: skySunDirection turned with the environment's
// rotation (environmentToWorld).
glm::vec3 skySunWorldDirection(const Environment& env, const SkyParams& sky);
// The sky's sun as a directional light of the same disk, radiance and color (docs/ibl.md, "The
// sky's sun as a light"): travelling along -(the sun's direction rotated with the environment),
// angular diameter twice the sun's radius, illuminance at normal incidence that of the disk of
// the sky's sun radiance times the environment's intensity. No shadows (renderedLights sets them
// for sky_sun: shadowed_light).
Light skySunLight(const Environment& env, const SkyParams& sky = {});

// Equirectangular mapping: u = atan2(d.x, -d.z) / (2 pi) + 0.5, v = acos(d.y) / pi (v = 0 at +Y,
// the top row); the image center (u = 0.5) looks down -Z.
glm::vec2 equirectUV(glm::vec3 dir);
glm::vec3 equirectDirection(glm::vec2 uv);

// Largest Radiance image width accepted (height: half of it): 16384 x 8192 decodes to 1.5 GiB of
// float RGB. Larger environments gain nothing at the engine's cube sizes (at most 4096 per face).
constexpr int kMaxHdrWidth = 16384;

// Loads an equirectangular Radiance RGBE (.hdr) file with the project's own decoder (header
// "#?RADIANCE" or "#?RGBE", FORMAT=32-bit_rle_rgbe, resolution "-Y H +X W", 2:1 aspect, at most
// kMaxHdrWidth wide). Scanlines are decoded as Radiance reads them: each one run-length encoded
// or flat (with old-style repeat pixels), the encoding free to change from one scanline to the
// next. The declared size is checked against the bytes that follow the header before anything is
// allocated, and every run against the data and the scanline, so a missing, truncated, oversized
// or corrupt file gives an IblError naming the file and the problem.
ImageRGBf loadHdr(const std::string& path);
// The same from the file's bytes (`path` names it in messages), at most `max_width` wide (fuzzers
// lower it to keep each run small).
ImageRGBf decodeHdr(const uint8_t* bytes, size_t size, const std::string& path,
                    int max_width = kMaxHdrWidth);
// What identifies an HDR file's contents to the caches built from it (the bake's, the sun's):
// its absolute path, size and modification time; empty where the file cannot be read.
std::string hdrFileIdentity(const std::string& path);
// Rec. 709 luminance, the weight the IBL code gives colours.
float luminance(glm::vec3 c);

// Source of an Environment (loads the .hdr for HdrFile). Throws IblError for kind None.
EnvSource makeEnvSource(const Environment& env, const SkyParams& sky = {});

// Source -> cube map of face size `size` (mip 0 only), each texel the mean of supersample^2
// stratified directions (bilinear fetches from an equirect).
CubeMapF envToCube(const EnvSource& src, int size, int supersample, int threads = 2);

struct BakeOptions {
  int cube_size = 0;          // 0: Environment::cube_size
  int prefilter_samples = 0;  // 0: Environment::prefilter_samples
  int min_mip_size = 8;       // last prefiltered mip (roughness 1) has this face size
  int supersample = 2;        // per axis, for envToCube (sky/uniform use at least 4)
  int env_brdf_size = 128;    // NoV x roughness table
  int env_brdf_samples = 1024;
  int irradiance_size = 32;  // 0: no irradiance cube map
  int threads = 2;           // worker threads (0: hardware concurrency)
  bool use_cache = true;
  std::string
      cache_dir;  // empty: $HV_CACHE_DIR, else $XDG_CACHE_HOME/halfvec, else ~/.cache/halfvec
  bool progress = true;  // progress lines on stderr
  BrdfConfig brdf;       // visibility term of the env BRDF table (see integrateEnvBrdf)
  SkyParams sky;
};

struct BakeTimings {
  double load_ms = 0.0;        // source load (.hdr decode)
  double convert_ms = 0.0;     // equirect/sky -> cube
  double prefilter_ms = 0.0;   // radiance mips
  double env_brdf_ms = 0.0;    // env BRDF table
  double sh_ms = 0.0;          // SH9 projection
  double irradiance_ms = 0.0;  // irradiance cube
  double cache_ms = 0.0;       // cache read (hit) or write (miss)
  double total_ms = 0.0;
  bool cache_hit = false;
};

struct IblBake {
  CubeMapF radiance;                // mip m: roughness mipToRoughness(m, mips - 1); mip 0 = source
  std::vector<glm::vec2> env_brdf;  // [roughness row][NoV column], (scale, bias) of Karis eq. 8
  int env_brdf_size = 0;            // texel centers: NoV = (i + 0.5) / size, same for roughness
  std::array<glm::vec3, 9> sh{};    // radiance SH9 coefficients (order in ibl.glsl)
  CubeMapF irradiance;              // E(n) (not divided by pi); empty if irradiance_size = 0
  BakeTimings timings;
};

// Env BRDF table (Karis 2013 eq. 8, IntegrateBRDF): GGX importance sampling (hammersley +
// importanceSampleGGX of shaders/common/sampling.glsl), the visibility term of brdf.v evaluated at
// alpha = roughness^2 without the Disney remap (evalVForAlpha; the default SchlickGGX is Karis's
// k = alpha / 2), Schlick Fresnel split into F0 scale and bias. Table layout: see IblBake.
std::vector<glm::vec2> integrateEnvBrdf(int size, int samples, int threads = 2,
                                        const BrdfConfig& brdf = {});
glm::vec2 integrateEnvBrdfAt(float NoV, float roughness, int samples, const BrdfConfig& brdf = {});
// Bilinear lookup of a table from integrateEnvBrdf (clamped to texel centers).
glm::vec2 lookupEnvBrdf(const std::vector<glm::vec2>& table, int size, float NoV, float roughness);

// Prefilters `source` (mip 0 = the environment, with a box-filtered mip chain used as the
// filtered-importance-sampling source) into mips of face size source.size >> m down to
// min_mip_size.
CubeMapF prefilterRadiance(const CubeMapF& source, int samples, int min_mip_size, int threads = 2,
                           bool progress = false);

std::array<glm::vec3, 9> projectSH9(const CubeMapF& cube);
// Brute-force cosine convolution of `cube` (read at the mip no larger than max(size, 16)).
CubeMapF irradianceCube(const CubeMapF& cube, int size, int threads = 2);

// Cache directory as described in BakeOptions::cache_dir.
std::string iblCacheDir(const BakeOptions& opt);

IblBake bakeEnvironment(const Environment& env, const BakeOptions& opt = {});

}  // namespace hv

// The render settings (`"settings"` of a scene file, docs/scene-format.md): their enums and ONE
// table, HV_RENDER_SETTINGS, with a row per setting. Everything that lists settings is generated
// from it: the RenderSettings struct, the scene loader's keys and parser, the scene writer, the
// variant key's canonical form, validation and the reasons of the manifest, the shader defines,
// the viewer's Render panel and the trade report's option rows. The enum values that reach the
// shaders are defined once, in shaders/common/setting_values.glsl, for GLSL and C++ alike.
//
// Adding a setting: one row below (and, for an enum, its type above with the values in
// setting_values.glsl and its names in enums.hpp), the shader code it selects, and a test.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "halfvec/shaders/common/setting_values.glsl"

namespace hv {

// Term choices; defaults are Karis 2013's choice (docs/brdf.md).
enum class DistributionTerm : uint8_t {
  GGX = HV_D_GGX,
  Beckmann = HV_D_BECKMANN,
  BlinnPhong = HV_D_BLINN_PHONG
};
enum class VisibilityTerm : uint8_t {
  SchlickGGX = HV_V_SCHLICK_GGX,  // k = alpha/2 (Karis 2013 eq. 4; remap_roughness for lights)
  SmithGGXCorrelated = HV_V_SMITH_GGX_CORRELATED,           // Heitz 2014 exact height-correlated
  SmithGGXCorrelatedFast = HV_V_SMITH_GGX_CORRELATED_FAST,  // Hammon 2017 / UE4 SmithJointApprox
  SmithGGXSeparable = HV_V_SMITH_GGX_SEPARABLE,             // Walter 2007 exact separable G1
  SmithBeckmannSeparable = HV_V_SMITH_BECKMANN_SEPARABLE,   // Walter 2007 rational approximation
  CookTorrance = HV_V_COOK_TORRANCE,
  Implicit = HV_V_IMPLICIT
};
enum class FresnelTerm : uint8_t {
  SchlickPow5 = HV_F_SCHLICK,
  SchlickSG = HV_F_SCHLICK_SG,
  Exact = HV_F_EXACT,
  SchlickF90Occlusion = HV_F_SCHLICK_F90_OCCLUSION
};
enum class DiffuseTerm : uint8_t { Lambert = HV_FD_LAMBERT, Burley = HV_FD_BURLEY };
enum class SphereDiffuse : uint8_t {
  KarisPoint = HV_SPHERE_DIFFUSE_KARIS_POINT,
  HorizonCorrect = HV_SPHERE_DIFFUSE_HORIZON
};
enum class SphereSpecular : uint8_t {
  RepresentativePoint = HV_SPHERE_SPECULAR_REPRESENTATIVE_POINT,
  Ltc = HV_SPHERE_SPECULAR_LTC
};
enum class TubeSpecular : uint8_t {
  ClosestPointEq19 = HV_TUBE_SPECULAR_CLOSEST_POINT,
  SmallestAngleEq18 = HV_TUBE_SPECULAR_SMALLEST_ANGLE,
  Ltc = HV_TUBE_SPECULAR_LTC
};
enum class TubeDiffuse : uint8_t {
  KarisEq16 = HV_TUBE_DIFFUSE_KARIS_EQ16,
  Ltc = HV_TUBE_DIFFUSE_LTC
};
// Flags in the shaders (HV_CULLING_BRUTE_FORCE, HV_ENV_BRDF_ANALYTIC, HV_IRRADIANCE_CUBEMAP): the
// second value is 1. Culling::Auto never reaches a shader: the variant key resolves it to Tiled or
// BruteForce from the scene's lights (render::chooseCulling, docs/performance.md "Culling only
// where it pays").
enum class Culling : uint8_t { Tiled = 0, BruteForce = 1, Auto = 2 };
enum class EnvBrdf : uint8_t { Table = 0, Analytic = 1 };
enum class Irradiance : uint8_t { SH9 = 0, Cubemap = 1 };
enum class IblDirection : uint8_t {
  Dominant = HV_IBL_DIRECTION_DOMINANT,
  Reflect = HV_IBL_DIRECTION_REFLECT
};
enum class ToneMap : uint8_t {
  Reinhard = HV_TONEMAP_REINHARD,
  ReinhardLuminance = HV_TONEMAP_REINHARD_LUMINANCE,
  None = HV_TONEMAP_NONE,
  PbrNeutral = HV_TONEMAP_PBR_NEUTRAL,
  Aces = HV_TONEMAP_ACES
};
enum class Gamma : uint8_t { Gamma22 = HV_GAMMA_22, SRGB = HV_GAMMA_SRGB };
// Shadows of lights with `shadows: true` (docs/lights.md, "Shadows").
enum class ShadowFilter : uint8_t {
  Hard = HV_SHADOW_FILTER_HARD,
  Pcf = HV_SHADOW_FILTER_PCF,
  Pcss = HV_SHADOW_FILTER_PCSS
};
// Screen-space ambient occlusion (docs/ambient-occlusion.md): none, or GTAO (Jimenez, Wu, Pesce,
// Jarabo 2016), its quality (directions x steps), resolution and specular occlusion.
enum class AmbientOcclusion : uint8_t { None = HV_AO_NONE, Gtao = HV_AO_GTAO };
enum class AoQuality : uint8_t {
  Low = HV_AO_QUALITY_LOW,
  Medium = HV_AO_QUALITY_MEDIUM,
  High = HV_AO_QUALITY_HIGH
};
enum class AoResolution : uint8_t { Full = HV_AO_RESOLUTION_FULL, Half = HV_AO_RESOLUTION_HALF };
enum class AoSpecular : uint8_t {
  None = HV_AO_SPECULAR_NONE,
  Lagarde = HV_AO_SPECULAR_LAGARDE,
  Cone = HV_AO_SPECULAR_CONE
};

// What part of a scene makes a setting change code. Without it the variant key resets the setting
// to its default (canonicalSettings), the manifest says why, and a key that holds another value is
// invalid (validateKey). The rules and their wording: engine/render/src/variant_key.cpp.
enum class SettingFeature : uint8_t {
  Frame,           // always in use (output size, tone mapping, the uber switch)
  Lights,          // any light: the BRDF terms, the falloff, culling
  SphereLights,    // sphere lights
  TubeLights,      // tube lights
  AmbientIbl,      // an environment lighting a default_lit material
  ShadowedLights,  // a light with `shadows: true`
  ScreenSpaceAo,   // `ao: gtao` where the ambient pass lights a default_lit material
};

// Another setting that makes this one change no code, and the value it then takes in the key.
enum class Supersede : uint8_t {
  None,
  RemapInapplicable,  // brdf.v is not Schlick-GGX: the remap has nothing to remap (Karis eq. 4)
  SphereLtc,          // sphere_specular ltc: it has no representative-point normalization
  TubeLtc,            // tube_specular ltc: likewise
  Gtao,               // ao gtao: ao_specular occludes the ambient specular instead
};

// Which pass's program the setting's define goes to.
enum class SettingPass : uint8_t { None, Light, Ambient, ToneMap, Ao };

// The descriptive columns of a row. Numbers: [lo, hi] (integers compare as integers, floats as
// the float they are stored in). `define` is the shader define; its value is the enum's value, the
// integer, or 1/0 for a bool. `trade`: an approximation option that `halfvec trade` varies, in
// `trade_group`. `label`: the viewer's Render panel shows it (nullptr: not shown);
// `needs_set_scene`: changing it re-uploads the scene (the irradiance cube is baked only when asked
// for).
struct SettingInfo {
  double lo = 0.0, hi = 0.0;
  bool lo_open = false;
  SettingFeature feature = SettingFeature::Frame;
  const char* define = nullptr;
  SettingPass pass = SettingPass::None;
  Supersede superseded_by = Supersede::None;
  bool superseded_value = false;
  bool trade = false;
  const char* trade_group = nullptr;
  const char* label = nullptr;
  bool needs_set_scene = false;
};

// X(TYPE, MEMBER, DEFAULT, KEY, INFO): one row per setting. KEY is the path under "settings" in a
// scene file, '.' between levels ("brdf.d" is {"settings": {"brdf": {"d": ...}}}). Row order is the
// order of the loader's key list, the writer, the manifest, the panel and the trade rows.
// clang-format off
#define HV_RENDER_SETTINGS(X)                                                                      \
  X(int, width, 960, "width", (SettingInfo{.lo = 1, .hi = 16384}))                                 \
  X(int, height, 540, "height", (SettingInfo{.lo = 1, .hi = 16384}))                               \
  X(float, exposure, 1.0f, "exposure", (SettingInfo{.lo = 1e-6, .hi = 1e6}))                       \
  X(ToneMap, tone_map, ToneMap::Reinhard, "tone_map",                                              \
    (SettingInfo{.define = "HV_TONEMAP", .pass = SettingPass::ToneMap, .label = "tone map"}))       \
  X(Gamma, gamma, Gamma::Gamma22, "gamma",                                                         \
    (SettingInfo{.define = "HV_GAMMA", .pass = SettingPass::ToneMap, .label = "gamma"}))            \
  X(bool, dither, true, "dither", (SettingInfo{.label = "dither"}))                                 \
  /* BRDF terms (Karis 2013, "Shading model"; docs/brdf.md) */                                      \
  X(DistributionTerm, d, DistributionTerm::GGX, "brdf.d",                                          \
    (SettingInfo{.feature = SettingFeature::Lights, .define = "HV_BRDF_D",                         \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "brdf",                 \
                 .label = "distribution (D)"}))                                                    \
  X(VisibilityTerm, v, VisibilityTerm::SchlickGGX, "brdf.v",                                       \
    (SettingInfo{.feature = SettingFeature::Lights, .define = "HV_BRDF_V",                         \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "brdf",                 \
                 .label = "visibility (V)"}))                                                      \
  X(FresnelTerm, f, FresnelTerm::SchlickPow5, "brdf.f",                                            \
    (SettingInfo{.feature = SettingFeature::Lights, .define = "HV_BRDF_F",                         \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "brdf",                 \
                 .label = "fresnel (F)"}))                                                         \
  X(DiffuseTerm, diffuse, DiffuseTerm::Lambert, "brdf.diffuse",                                    \
    (SettingInfo{.feature = SettingFeature::Lights, .define = "HV_BRDF_FD",                        \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "brdf",                 \
                 .label = "diffuse"}))                                                             \
  /* Disney's (roughness+1)/2 for analytic lights (Karis eq. 4) */                                 \
  X(bool, remap_roughness, true, "brdf.remap_roughness",                                           \
    (SettingInfo{.feature = SettingFeature::Lights, .define = "HV_REMAP_ROUGHNESS",                \
                 .pass = SettingPass::Light, .superseded_by = Supersede::RemapInapplicable,        \
                 .superseded_value = false, .trade = true, .trade_group = "brdf",                  \
                 .label = "remap roughness (analytic)"}))                                          \
  /* UE4's 1/(d^2+1) (Karis eq. 9); false: the physical 1/d^2 */                                   \
  X(bool, falloff_plus_one, true, "falloff_plus_one",                                              \
    (SettingInfo{.feature = SettingFeature::Lights, .define = "HV_FALLOFF_PLUS_ONE",               \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights",               \
                 .label = "falloff 1/(d^2+1)"}))                                                   \
  X(SphereDiffuse, sphere_diffuse, SphereDiffuse::KarisPoint, "sphere_diffuse",                    \
    (SettingInfo{.feature = SettingFeature::SphereLights, .define = "HV_SPHERE_DIFFUSE",           \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights",               \
                 .label = "sphere diffuse"}))                                                      \
  /* (alpha/alpha')^2, Karis eqs. 10 and 14 */                                                     \
  X(bool, sphere_normalization, true, "sphere_normalization",                                      \
    (SettingInfo{.feature = SettingFeature::SphereLights, .define = "HV_SPHERE_NORMALIZATION",     \
                 .pass = SettingPass::Light, .superseded_by = Supersede::SphereLtc,                \
                 .superseded_value = true, .trade = true, .trade_group = "lights",                 \
                 .label = "sphere normalization"}))                                                \
  /* Karis's representative point, or the fitted LTC over the sphere (docs/lights.md) */           \
  X(SphereSpecular, sphere_specular, SphereSpecular::RepresentativePoint, "sphere_specular",       \
    (SettingInfo{.feature = SettingFeature::SphereLights, .define = "HV_SPHERE_SPECULAR",          \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights",               \
                 .label = "sphere specular"}))                                                     \
  X(TubeSpecular, tube_specular, TubeSpecular::ClosestPointEq19, "tube_specular",                  \
    (SettingInfo{.feature = SettingFeature::TubeLights, .define = "HV_TUBE_SPECULAR",              \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights",               \
                 .label = "tube specular"}))                                                       \
  /* alpha/alpha', Karis eq. 20 */                                                                 \
  X(bool, tube_normalization, true, "tube_normalization",                                          \
    (SettingInfo{.feature = SettingFeature::TubeLights, .define = "HV_TUBE_NORMALIZATION",         \
                 .pass = SettingPass::Light, .superseded_by = Supersede::TubeLtc,                  \
                 .superseded_value = true, .trade = true, .trade_group = "lights",                 \
                 .label = "tube normalization"}))                                                  \
  /* Karis eq. 16, or the capsule's exact-shape irradiance */                                      \
  X(TubeDiffuse, tube_diffuse, TubeDiffuse::KarisEq16, "tube_diffuse",                             \
    (SettingInfo{.feature = SettingFeature::TubeLights, .define = "HV_TUBE_DIFFUSE",               \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights",               \
                 .label = "tube diffuse"}))                                                        \
  /* auto: brute force below the crossover the variant key measures (docs/performance.md) */       \
  X(Culling, culling, Culling::Auto, "culling",                                                    \
    (SettingInfo{.feature = SettingFeature::Lights, .define = "HV_CULLING_BRUTE_FORCE",            \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "culling",              \
                 .label = "culling"}))                                                             \
  /* Image-based lighting (docs/ibl.md) */                                                         \
  X(EnvBrdf, env_brdf, EnvBrdf::Table, "env_brdf",                                                 \
    (SettingInfo{.feature = SettingFeature::AmbientIbl, .define = "HV_ENV_BRDF_ANALYTIC",          \
                 .pass = SettingPass::Ambient, .trade = true, .trade_group = "environment",        \
                 .label = "env BRDF"}))                                                            \
  X(bool, energy_compensation, false, "energy_compensation",                                       \
    (SettingInfo{.feature = SettingFeature::AmbientIbl, .define = "HV_ENERGY_COMPENSATION",        \
                 .pass = SettingPass::Ambient, .trade = true, .trade_group = "environment",        \
                 .label = "energy compensation"}))                                                 \
  X(Irradiance, irradiance, Irradiance::SH9, "irradiance",                                         \
    (SettingInfo{.feature = SettingFeature::AmbientIbl, .define = "HV_IRRADIANCE_CUBEMAP",         \
                 .pass = SettingPass::Ambient, .trade = true, .trade_group = "environment",        \
                 .label = "irradiance", .needs_set_scene = true}))                                 \
  /* dominant direction (Lagarde & de Rousiers 2014) or R (Karis 2013); docs/ibl.md */             \
  X(IblDirection, ibl_direction, IblDirection::Dominant, "ibl_direction",                          \
    (SettingInfo{.feature = SettingFeature::AmbientIbl, .define = "HV_IBL_DIRECTION",              \
                 .pass = SettingPass::Ambient, .trade = true, .trade_group = "environment",        \
                 .label = "IBL direction"}))                                                       \
  X(bool, specular_occlusion, false, "specular_occlusion",                                         \
    (SettingInfo{.feature = SettingFeature::AmbientIbl, .define = "HV_SPECULAR_OCCLUSION",         \
                 .pass = SettingPass::Ambient, .superseded_by = Supersede::Gtao,                   \
                 .superseded_value = false, .trade = true, .trade_group = "environment",           \
                 .label = "specular occlusion"}))                                                  \
  /* Screen-space ambient occlusion (docs/ambient-occlusion.md) */                                 \
  X(AmbientOcclusion, ao, AmbientOcclusion::None, "ao",                                            \
    (SettingInfo{.feature = SettingFeature::AmbientIbl, .define = "HV_AO",                         \
                 .pass = SettingPass::Ambient, .trade = true, .trade_group = "occlusion",          \
                 .label = "ambient occlusion"}))                                                   \
  /* metres: the horizon search's reach, and the distance beyond which nothing occludes */          \
  X(float, ao_radius, 1.0f, "ao_radius",                                                           \
    (SettingInfo{.lo = 0.0, .hi = 1e4, .lo_open = true,                                            \
                 .feature = SettingFeature::ScreenSpaceAo}))                                       \
  X(AoQuality, ao_quality, AoQuality::Medium, "ao_quality",                                        \
    (SettingInfo{.feature = SettingFeature::ScreenSpaceAo, .define = "HV_AO_QUALITY",              \
                 .pass = SettingPass::Ao, .label = "AO quality"}))                                 \
  X(AoResolution, ao_resolution, AoResolution::Half, "ao_resolution",                              \
    (SettingInfo{.feature = SettingFeature::ScreenSpaceAo, .define = "HV_AO_HALF_RESOLUTION",      \
                 .pass = SettingPass::Ao, .label = "AO resolution"}))                              \
  X(AoSpecular, ao_specular, AoSpecular::Lagarde, "ao_specular",                                   \
    (SettingInfo{.feature = SettingFeature::ScreenSpaceAo, .define = "HV_AO_SPECULAR",             \
                 .pass = SettingPass::Ambient, .label = "AO specular occlusion"}))                 \
  /* Jimenez et al. 2016 section 5: interreflection from albedo (the reference has none) */      \
  X(bool, ao_multi_bounce, false, "ao_multi_bounce",                                               \
    (SettingInfo{.feature = SettingFeature::ScreenSpaceAo, .define = "HV_AO_MULTI_BOUNCE",         \
                 .pass = SettingPass::Ambient, .label = "AO multi-bounce"}))                       \
  /* Shadows (docs/lights.md, "Shadows"); the face size sets how many lights the atlas holds */     \
  /* no label: the Lights panel picks the filter */                                                \
  X(ShadowFilter, shadow_filter, ShadowFilter::Pcss, "shadow_filter",                              \
    (SettingInfo{.feature = SettingFeature::ShadowedLights, .define = "HV_SHADOW_FILTER",          \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights"}))             \
  X(int, shadow_map_size, 1024, "shadow_map_size",                                                 \
    (SettingInfo{.lo = 16, .hi = 2048, .feature = SettingFeature::ShadowedLights,                  \
                 .define = "HV_SHADOW_MAP_SIZE", .pass = SettingPass::Light, .trade = true,        \
                 .trade_group = "lights"}))                                                        \
  /* every feature compiled in, chosen at run time (docs/variants.md) */                           \
  X(bool, uber, false, "uber", (SettingInfo{}))
// clang-format on

struct RenderSettings {
#define HV_SETTING_MEMBER(TYPE, MEMBER, DEFAULT, KEY, INFO) TYPE MEMBER = DEFAULT;
  HV_RENDER_SETTINGS(HV_SETTING_MEMBER)
#undef HV_SETTING_MEMBER
  bool operator==(const RenderSettings&) const = default;
  // Term masks (not scene-file fields; `halfvec render --aov` sets them): bit 1 diffuse, bit 2
  // specular of direct light (HV_DIRECT_TERMS) and of ambient light (HV_AMBIENT_TERMS).
  uint8_t direct_terms = 3;
  uint8_t ambient_terms = 3;
};

// One row of the table, typed: its key, member, default and descriptive columns.
template <class T>
struct SettingRow {
  using Type = T;
  const char* key;
  T RenderSettings::*member;
  T default_value;
  SettingInfo info;
};

// Calls f(row) for every row, in table order (f is generic over the row's type).
template <class F>
constexpr void forEachSetting(F&& f) {
#define HV_SETTING_ROW(TYPE, MEMBER, DEFAULT, KEY, INFO) \
  f(SettingRow<TYPE>{KEY, &RenderSettings::MEMBER, DEFAULT, INFO});
  HV_RENDER_SETTINGS(HV_SETTING_ROW)
#undef HV_SETTING_ROW
}

// The defines the rows of `pass` give its program, in row order: (HV_BRDF_D, "0"), ...; an enum's
// value, "1" / "0" for a bool.
std::vector<std::pair<std::string, std::string>> settingDefines(const RenderSettings& s,
                                                                SettingPass pass);

}  // namespace hv

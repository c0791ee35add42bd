// The render settings (`"settings"` of a scene file, docs/scene-format.md): their enums and ONE
// table, HV_RENDER_SETTINGS, with a row per setting. Everything that lists settings is generated
// from it: the RenderSettings struct, the scene loader's keys and parser, the scene writer, the
// variant key's canonical form, validation and the reasons of the manifest, the shader defines,
// the viewer's Render panel, the trade report's option rows, and the values the shaders compare
// the defines against (shaders/common/setting_values.glsl, generated from the value lists below
// by hv_setting_values; the build fails while it is stale).
//
// Adding a setting: one row below (and, for an enum, its list of values above), the shader code
// it selects, and a test; then regenerate setting_values.glsl when the list names a define:
//   build/shaders/hv_setting_values --out shaders/common/setting_values.glsl
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hv {

template <class E>
struct EnumNames;  // names of an enum's values, indexed by value (halfvec/scene/enums.hpp)

// An enumerated setting's values, each V(ENUMERATOR, "scene-file name", DEFINE): the value is its
// position in the list (0, 1, 2, ...; the names are indexed by value), and DEFINE the name of the
// GLSL define of that value the shaders compare against, written into setting_values.glsl by
// settingValuesGlsl(). A flag's list (its define is 0 or 1) gives the numbers instead, which
// define nothing. HV_SETTING_ENUM declares the enum class, its names and its define names from one
// list.
#define HV_SETTING_ENUMERATOR(NAME, STR, DEFINE) NAME,
#define HV_SETTING_ENUM_NAME(NAME, STR, DEFINE) STR,
#define HV_SETTING_ENUM_DEFINE(NAME, STR, DEFINE) #DEFINE,
#define HV_SETTING_ENUM(E, VALUES)                                         \
  enum class E : uint8_t { VALUES(HV_SETTING_ENUMERATOR) };                \
  template <>                                                              \
  struct EnumNames<E> {                                                    \
    static constexpr std::array names =                                    \
        std::to_array<std::string_view>({VALUES(HV_SETTING_ENUM_NAME)});   \
    static constexpr std::array defines =                                  \
        std::to_array<std::string_view>({VALUES(HV_SETTING_ENUM_DEFINE)}); \
  }

// Term choices; defaults are Karis 2013's choice (docs/brdf.md).
// brdf.d: the microfacet distribution (Karis 2013, "Specular D").
#define HV_DISTRIBUTION_TERMS(V)         \
  V(GGX, "ggx", HV_D_GGX)                \
  V(Beckmann, "beckmann", HV_D_BECKMANN) \
  V(BlinnPhong, "blinn_phong", HV_D_BLINN_PHONG)
HV_SETTING_ENUM(DistributionTerm, HV_DISTRIBUTION_TERMS);
// brdf.v: the visibility term G / (4 NoL NoV) (Karis 2013, "Specular G").
#define HV_VISIBILITY_TERMS(V)                                                           \
  /* k = alpha/2 (Karis 2013 eq. 4; remap_roughness for lights) */                       \
  V(SchlickGGX, "schlick_ggx", HV_V_SCHLICK_GGX)                                         \
  /* Heitz 2014 exact height-correlated */                                               \
  V(SmithGGXCorrelated, "smith_ggx_correlated", HV_V_SMITH_GGX_CORRELATED)               \
  /* Hammon 2017 / UE4 SmithJointApprox */                                               \
  V(SmithGGXCorrelatedFast, "smith_ggx_correlated_fast", HV_V_SMITH_GGX_CORRELATED_FAST) \
  /* Walter 2007 exact separable G1 */                                                   \
  V(SmithGGXSeparable, "smith_ggx_separable", HV_V_SMITH_GGX_SEPARABLE)                  \
  /* Walter 2007 rational approximation */                                               \
  V(SmithBeckmannSeparable, "smith_beckmann_separable", HV_V_SMITH_BECKMANN_SEPARABLE)   \
  V(CookTorrance, "cook_torrance", HV_V_COOK_TORRANCE)                                   \
  V(Implicit, "implicit", HV_V_IMPLICIT)
HV_SETTING_ENUM(VisibilityTerm, HV_VISIBILITY_TERMS);
// brdf.f: Fresnel (Karis 2013, "Specular F").
#define HV_FRESNEL_TERMS(V)                    \
  V(SchlickPow5, "schlick_pow5", HV_F_SCHLICK) \
  V(SchlickSG, "schlick_sg", HV_F_SCHLICK_SG)  \
  V(Exact, "exact", HV_F_EXACT)                \
  V(SchlickF90Occlusion, "schlick_f90_occlusion", HV_F_SCHLICK_F90_OCCLUSION)
HV_SETTING_ENUM(FresnelTerm, HV_FRESNEL_TERMS);
#define HV_DIFFUSE_TERMS(V) V(Lambert, "lambert", HV_FD_LAMBERT) V(Burley, "burley", HV_FD_BURLEY)
HV_SETTING_ENUM(DiffuseTerm, HV_DIFFUSE_TERMS);
// sphere_diffuse: Karis's point approximation or the horizon-correct sphere irradiance (Lagarde
// & de Rousiers 2014, section 4.7).
#define HV_SPHERE_DIFFUSES(V)                                 \
  V(KarisPoint, "karis_point", HV_SPHERE_DIFFUSE_KARIS_POINT) \
  V(HorizonCorrect, "horizon_correct", HV_SPHERE_DIFFUSE_HORIZON)
HV_SETTING_ENUM(SphereDiffuse, HV_SPHERE_DIFFUSES);
// sphere_specular: representative point (Karis 2013 eqs. 10, 11, 14) or LTC (docs/lights.md).
#define HV_SPHERE_SPECULARS(V)                                                            \
  V(RepresentativePoint, "representative_point", HV_SPHERE_SPECULAR_REPRESENTATIVE_POINT) \
  V(Ltc, "ltc", HV_SPHERE_SPECULAR_LTC)
HV_SETTING_ENUM(SphereSpecular, HV_SPHERE_SPECULARS);
// tube_specular: closest point to the reflection ray (Karis 2013 eq. 19), smallest angle
// (eq. 18), LTC over the capsule.
#define HV_TUBE_SPECULARS(V)                                                   \
  V(ClosestPointEq19, "closest_point_eq19", HV_TUBE_SPECULAR_CLOSEST_POINT)    \
  V(SmallestAngleEq18, "smallest_angle_eq18", HV_TUBE_SPECULAR_SMALLEST_ANGLE) \
  V(Ltc, "ltc", HV_TUBE_SPECULAR_LTC)
HV_SETTING_ENUM(TubeSpecular, HV_TUBE_SPECULARS);
// tube_diffuse: Karis 2013 eq. 16 or the capsule's irradiance (identity LTC).
#define HV_TUBE_DIFFUSES(V) \
  V(KarisEq16, "karis_eq16", HV_TUBE_DIFFUSE_KARIS_EQ16) V(Ltc, "ltc", HV_TUBE_DIFFUSE_LTC)
HV_SETTING_ENUM(TubeDiffuse, HV_TUBE_DIFFUSES);
// Flags in the shaders (HV_CULLING_BRUTE_FORCE, HV_ENV_BRDF_ANALYTIC, HV_IRRADIANCE_CUBEMAP): the
// second value is 1. Culling::Auto never reaches a shader: the variant key resolves it to Tiled or
// BruteForce from the scene's lights (render::chooseCulling, docs/performance.md "Culling only
// where it pays").
#define HV_CULLINGS(V) V(Tiled, "tiled", 0) V(BruteForce, "brute_force", 1) V(Auto, "auto", 2)
HV_SETTING_ENUM(Culling, HV_CULLINGS);
#define HV_ENV_BRDFS(V) V(Table, "table", 0) V(Analytic, "analytic", 1)
HV_SETTING_ENUM(EnvBrdf, HV_ENV_BRDFS);
#define HV_IRRADIANCES(V) V(SH9, "sh9", 0) V(Cubemap, "cubemap", 1)
HV_SETTING_ENUM(Irradiance, HV_IRRADIANCES);
// ibl_direction: the prefiltered radiance is read along the dominant direction of the specular
// lobe (Lagarde & de Rousiers 2014, section 4.9.3) or the mirror direction R (Karis 2013).
#define HV_IBL_DIRECTIONS(V)                         \
  V(Dominant, "dominant", HV_IBL_DIRECTION_DOMINANT) \
  V(Reflect, "reflect", HV_IBL_DIRECTION_REFLECT)
HV_SETTING_ENUM(IblDirection, HV_IBL_DIRECTIONS);
// ibl_specular: the split sum's one prefiltered texel (Karis 2013 eq. 8), or the radiance
// averaged over samples of the pixel's own lobe times the same env BRDF (docs/ibl.md).
#define HV_IBL_SPECULARS(V)                           \
  V(SplitSum, "split_sum", HV_IBL_SPECULAR_SPLIT_SUM) \
  V(Sampled, "sampled", HV_IBL_SPECULAR_SAMPLED)
HV_SETTING_ENUM(IblSpecular, HV_IBL_SPECULARS);
// sky_sun: the environment's sun (the procedural sky's, or an HDR's: halfvec/ibl/hdr_sun.hpp) in
// the prefiltered environment, or left out of it and drawn as a directional light of the same
// disk, without or with its shadow (docs/ibl.md, "The sky's sun as a light", "An HDR's sun as a
// light").
#define HV_SKY_SUNS(V) \
  V(Environment, "environment", 0) V(Light, "light", 1) V(ShadowedLight, "shadowed_light", 2)
HV_SETTING_ENUM(SkySun, HV_SKY_SUNS);
// tone_map: Reinhard per channel (Reinhard et al. 2002, eq. 3), on luminance, none (clamp),
// Khronos PBR Neutral, ACES (Narkowicz's fit).
#define HV_TONE_MAPS(V)                                                     \
  V(Reinhard, "reinhard", HV_TONEMAP_REINHARD)                              \
  V(ReinhardLuminance, "reinhard_luminance", HV_TONEMAP_REINHARD_LUMINANCE) \
  V(None, "none", HV_TONEMAP_NONE)                                          \
  V(PbrNeutral, "pbr_neutral", HV_TONEMAP_PBR_NEUTRAL)                      \
  V(Aces, "aces", HV_TONEMAP_ACES)
HV_SETTING_ENUM(ToneMap, HV_TONE_MAPS);
// gamma: gamma 2.2 or exact sRGB (IEC 61966-2-1).
#define HV_GAMMAS(V) V(Gamma22, "gamma22", HV_GAMMA_22) V(SRGB, "srgb", HV_GAMMA_SRGB)
HV_SETTING_ENUM(Gamma, HV_GAMMAS);
// Shadows of lights with `shadows: true` (docs/lights.md, "Shadows").
#define HV_SHADOW_FILTERS(V)             \
  V(Hard, "hard", HV_SHADOW_FILTER_HARD) \
  V(Pcf, "pcf", HV_SHADOW_FILTER_PCF)    \
  V(Pcss, "pcss", HV_SHADOW_FILTER_PCSS)
HV_SETTING_ENUM(ShadowFilter, HV_SHADOW_FILTERS);
// Where the shadowed lights' visibility is computed: per pixel inside the light pass, or once per
// 2x2 pixels in a pass of its own, upsampled by depth and normal (docs/lights.md, "Shadows").
#define HV_SHADOW_RESOLUTIONS(V) \
  V(Full, "full", HV_SHADOW_RESOLUTION_FULL) V(Half, "half", HV_SHADOW_RESOLUTION_HALF)
HV_SETTING_ENUM(ShadowResolution, HV_SHADOW_RESOLUTIONS);
// How densely PCSS's blocker search covers the emitter (docs/lights.md, "Shadow quality"): 8
// gathers, or 32 (more accurate penumbrae, no bands under long tubes, a dearer light pass).
#define HV_SHADOW_QUALITIES(V) \
  V(Medium, "medium", HV_SHADOW_QUALITY_MEDIUM) V(High, "high", HV_SHADOW_QUALITY_HIGH)
HV_SETTING_ENUM(ShadowQuality, HV_SHADOW_QUALITIES);
// Screen-space ambient occlusion (docs/ambient-occlusion.md): none, or GTAO (Jimenez, Wu, Pesce,
// Jarabo 2016), its quality (directions x steps), resolution and specular occlusion.
#define HV_AMBIENT_OCCLUSIONS(V) V(None, "none", HV_AO_NONE) V(Gtao, "gtao", HV_AO_GTAO)
HV_SETTING_ENUM(AmbientOcclusion, HV_AMBIENT_OCCLUSIONS);
#define HV_AO_QUALITIES(V)                  \
  V(Low, "low", HV_AO_QUALITY_LOW)          \
  V(Medium, "medium", HV_AO_QUALITY_MEDIUM) \
  V(High, "high", HV_AO_QUALITY_HIGH)
HV_SETTING_ENUM(AoQuality, HV_AO_QUALITIES);
#define HV_AO_RESOLUTIONS(V) \
  V(Full, "full", HV_AO_RESOLUTION_FULL) V(Half, "half", HV_AO_RESOLUTION_HALF)
HV_SETTING_ENUM(AoResolution, HV_AO_RESOLUTIONS);
#define HV_AO_SPECULARS(V)                      \
  V(None, "none", HV_AO_SPECULAR_NONE)          \
  V(Lagarde, "lagarde", HV_AO_SPECULAR_LAGARDE) \
  V(Cone, "cone", HV_AO_SPECULAR_CONE)          \
  V(Traced, "traced", HV_AO_SPECULAR_TRACED)
HV_SETTING_ENUM(AoSpecular, HV_AO_SPECULARS);

// What part of a scene makes a setting change code. Without it the variant key resets the setting
// to its default (canonicalSettings), the manifest says why, and a key that holds another value is
// invalid (validateKey). The rules and their wording: engine/render/src/variant_key.cpp.
enum class SettingFeature : uint8_t {
  Frame,           // always in use (output size, tone mapping, the uber switch)
  Lights,          // any light: the BRDF terms, the falloff, culling
  SphereLights,    // sphere lights, and directional lights (shaded as a sphere at infinity)
  TubeLights,      // tube lights
  AmbientIbl,      // an environment lighting a default_lit material
  ShadowedLights,  // a light with `shadows: true`
  ScreenSpaceAo,   // `ao: gtao` where the ambient pass lights a default_lit material
  EnvironmentSun,  // the environment has a sun: the procedural sky's or an HDR's (sky_sun.hpp)
  VaryingAmbient,  // AmbientIbl with an environment that is not uniform (its radiance varies)
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
// integer, 1/0 for a bool, or for a float 1 when it is not 0 (the float itself reaches the
// shaders in the frame block: it switches code on, its value changes no code). `trade`: an
// approximation option that `halfvec trade` varies, in `trade_group`. `label`: the viewer's Render
// panel shows it (nullptr: not shown); `needs_set_scene`: changing it re-uploads the scene (the
// irradiance cube is baked only when asked for).
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
  // A float's trade rows: these values (0: none), each where it differs from the scene's.
  std::array<double, 5> trade_values{};
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
  /* the error budget: the representative point's predicted relative error per pixel-light */    \
  /* pair above which that pair takes the LTC; 0: none (error_budget.glsl, docs/lights.md) */       \
  X(float, max_error, 0.0f, "max_error",                                                           \
    (SettingInfo{.lo = 0.0, .hi = 1.0, .feature = SettingFeature::SphereLights,                    \
                 .define = "HV_ERROR_BUDGET", .pass = SettingPass::Light, .trade = true,           \
                 .trade_group = "lights", .trade_values = {0.01, 0.02, 0.05, 0.1, 0.2},           \
                 .label = "max error (budget)"}))                                                 \
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
  /* split sum (Karis 2013 eq. 8) or the lobe's mean radiance from 16 samples; docs/ibl.md */       \
  X(IblSpecular, ibl_specular, IblSpecular::SplitSum, "ibl_specular",                              \
    (SettingInfo{.feature = SettingFeature::VaryingAmbient, .define = "HV_IBL_SPECULAR",               \
                 .pass = SettingPass::Ambient, .trade = true, .trade_group = "environment",        \
                 .label = "IBL specular"}))                                                        \
  /* the environment's sun in it or as a directional light; docs/ibl.md */                 \
  X(SkySun, sky_sun, SkySun::Light, "sky_sun",                                                    \
    (SettingInfo{.feature = SettingFeature::EnvironmentSun, .trade = true,                         \
                 .trade_group = "environment", .label = "sky sun", .needs_set_scene = true}))     \
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
  X(ShadowResolution, shadow_resolution, ShadowResolution::Full, "shadow_resolution",              \
    (SettingInfo{.feature = SettingFeature::ShadowedLights, .define = "HV_SHADOW_RESOLUTION",      \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights",               \
                 .label = "shadow resolution"}))                                                   \
  X(ShadowQuality, shadow_quality, ShadowQuality::Medium, "shadow_quality",                        \
    (SettingInfo{.feature = SettingFeature::ShadowedLights, .define = "HV_SHADOW_QUALITY",         \
                 .pass = SettingPass::Light, .trade = true, .trade_group = "lights",               \
                 .label = "shadow quality"}))                                                      \
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

// The text of shaders/common/setting_values.glsl: a `#define` per value of every enumerated
// setting whose list names defines (HV_SETTING_ENUM), numbered by its position, in row order.
std::string settingValuesGlsl();

}  // namespace hv

// Scene-driven shader specialization (docs/variants.md). The VariantKey says what a loaded scene
// needs: light types, shading models, environment, the material features of each material and
// the BRDF / approximation settings that change code. Each pass is compiled from it, so a scene
// without tube lights contains no tube-light code and a material without a normal map no
// normal-map code. The rules (which combinations are valid, which settings imply which code) are
// plain functions, unit-tested in tests/render/test_variant_key.cpp. No GL here.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "halfvec/scene/scene.hpp"

namespace hv::render {

// What the G-buffer program of one material must contain. Each field is one define
// (HV_MAT_<NAME>); a material whose field is off gets a program without that code.
struct MaterialFeatures {
  bool base_color_map = false;   // baseColorTexture
  bool metal_rough_map = false;  // metallicRoughnessTexture
  bool normal_map = false;       // normalTexture (needs the vertex tangent)
  bool occlusion_map = false;    // occlusionTexture with strength != 0 (0 leaves Cavity as is)
  bool emissive = false;         // emissive radiance != 0 (else the HDR target gets 0)
  bool emissive_map = false;     // emissiveTexture; only with emissive (it scales the constant)
  bool alpha_mask = false;       // alpha_mode mask: alpha test and discard
  bool double_sided = false;     // back faces are drawn and flip the normal
  bool uv1 = false;              // an enabled map reads TEXCOORD_1 (else only TEXCOORD_0 exists)
  bool vertex_color = false;     // a mesh drawn with it has COLOR_0 and the material uses it
  bool tex_transform = false;    // an enabled map has a KHR_texture_transform
  bool clear_coat = false;       // shading model clear_coat: writes the G-buffer's coat target
  bool clear_coat_maps = false;  // a clear_coat material with a coat texture (weight, roughness,
                                 // normal); read by the G-buffer pass only

  auto operator<=>(const MaterialFeatures&) const = default;
  // Compact text of the enabled features, e.g. "base_color_map+normal_map"; "none" if none.
  std::string text() const;
};

// One row of the feature table: define name, scene-format name, member.
struct MaterialFeatureField {
  const char* define;  // HV_MAT_NORMAL_MAP
  const char* name;    // normal_map
  bool MaterialFeatures::*member;
};
const std::array<MaterialFeatureField, 13>& materialFeatureFields();

// The features a material uses, after the rules above (emissive map only with emissive,
// occlusion map only with strength != 0, uv1 only if an enabled map reads set 1).
MaterialFeatures materialFeatures(const Material& m, bool colored_mesh = false);
// Every feature on: the uber G-buffer program, which reads the material flags at run time.
MaterialFeatures allMaterialFeatures();

// What `culling: auto` means for a scene: brute force (every light at every pixel, no culling
// pass) where culling cannot pay for itself, tiled culling elsewhere. Culling costs a fixed
// bounds pass and saves the evaluations of the lights a pixel's tile does not list; so brute force
// when there are at most kAutoCullingMaxLights lights and the evaluations per pixel culling would
// save (the lights minus their coverage) are at most kAutoCullingSavedLights. The constants are
// the measured crossover (docs/performance.md, "Culling only where it pays").
inline constexpr size_t kAutoCullingMaxLights = 2;
inline constexpr double kAutoCullingSavedLights = 0.5;
struct CullingChoice {
  Culling culling = Culling::Tiled;
  size_t lights = 0;
  // Lights per tile: the tiles of the lights' tile rectangles (sphereTileRect, as the culling
  // bins them) at the scene's camera and settings.width x height, over the screen's tiles.
  double coverage = 0.0;
  std::string why;  // for the manifest
};
CullingChoice chooseCulling(const Scene& scene);

struct VariantKey {
  // Light shapes present (count > 0; a spot counts as its shape, lightShape); the light programs
  // compile only these. spot_lights: some light is a spot, whose cone the point and sphere code
  // then contains (HV_HAS_SPOT_LIGHTS).
  bool point_lights = false, sphere_lights = false, tube_lights = false, spot_lights = false;
  // Some light is directional: the light and forward passes then loop over the frame's
  // directional lights at every pixel (HV_HAS_DIRECTIONAL_LIGHTS).
  bool directional_lights = false;
  // Shading models present among the materials drawn. Background (no geometry) is always
  // possible, so it has no flag: the ambient pass always writes it.
  // default_lit: a lit material (default_lit or clear_coat); clear_coat: a clear_coat material,
  // whose coat target the G-buffer then has and whose branch the light and ambient passes
  // compile (HV_HAS_CLEAR_COAT).
  bool unlit = false, default_lit = false, clear_coat = false;
  EnvironmentKind environment = EnvironmentKind::None;
  // The environment has a sun that settings.sky_sun may draw as a light (environmentHasSun).
  bool environment_sun = false;
  // A light casts shadows (Light::shadows): the light programs contain the shadow lookup
  // (shaders/common/shadows.glsl) and the frame starts with the shadow-map pass.
  bool shadows = false;
  // `settings.ao: gtao` where the ambient pass lights a default_lit material: the frame has the AO
  // pass (shaders/passes/gtao.comp) and the ambient pass reads its output.
  bool ao = false;
  // A drawn material has alpha_mode blend: the frame ends its lighting with the forward pass of
  // blended surfaces (shaders/passes/forward.frag), which draws them instead of the G-buffer pass.
  bool blend = false;
  // The distinct feature sets, one G-buffer program each, and each material's index into it.
  std::vector<MaterialFeatures> material_variants;
  std::vector<int> material_variant;
  // The scene's settings with those that change no code in this scene reset to their defaults
  // (canonicalSettings), so equal code gets equal keys; culling auto resolved (a key without
  // lights: tiled).
  RenderSettings settings = [] {
    RenderSettings r;
    r.culling = Culling::Tiled;
    return r;
  }();
  // culling: auto resolved for this scene (settings.culling holds the result, never Auto).
  CullingChoice auto_culling;
  bool uber = false;  // every feature compiled in, chosen at run time

  bool hasLights() const {
    return point_lights || sphere_lights || tube_lights || directional_lights;
  }
  bool hasEnvironment() const { return environment != EnvironmentKind::None; }
  // Whether the ambient pass contains image-based lighting of lit surfaces.
  bool ambientIbl() const { return hasEnvironment() && (default_lit || uber); }
  // One line, e.g. "lights point+tube; models default_lit+unlit; environment sky; 3 material
  // variants; specialized".
  std::string text() const;
};

// Derives the key of a loaded scene. With settings.uber every light type, shading model and
// material feature is on (environment and BRDF settings still come from the scene).
VariantKey deriveVariantKey(const Scene& scene);

// Rules: which settings change code in a scene with these contents.
// The roughness remap changes only visibility terms that depend on alpha (not Cook-Torrance or
// implicit); see brdf.glsl visibility().
bool remapMeaningful(VisibilityTerm v);
// Settings reset to their defaults where they change no code: BRDF terms and falloff without
// lights; sphere options without spheres; tube options without tubes; culling without lights;
// the ambient options without ambient IBL; the remap where remapMeaningful is false.
RenderSettings canonicalSettings(const RenderSettings& s, const VariantKey& key);

// Reasons a key is invalid (empty if valid): an irradiance cubemap or other IBL option without
// environment, sphere/tube options without those lights, a remap with a V term it cannot change,
// an emissive map without emissive, uv1 without any map, a material index out of range...
std::vector<std::string> validateKey(const VariantKey& key);

// A define of a pass program with the reason it has this value (the manifest prints both).
struct KeyDefine {
  std::string name, value, why;
};

// G-buffer pass (gbuffer.vert/.frag), material variant `variant` of the key.
std::vector<KeyDefine> gbufferDefines(const VariantKey& key, size_t variant, const Scene& scene);
// Light culling and light passes: BRDF terms, light options, light types, culling.
std::vector<KeyDefine> lightDefines(const VariantKey& key, const Scene& scene);
// Ambient pass: environment presence, shading models, the IBL options.
std::vector<KeyDefine> ambientDefines(const VariantKey& key, const Scene& scene);
// Forward pass of blended surfaces (forward.frag), material variant `variant`: the G-buffer
// program's material defines and the light and ambient programs' defines, so a blended surface is
// shaded by the same approximations as an opaque one.
std::vector<KeyDefine> forwardDefines(const VariantKey& key, size_t variant, const Scene& scene);
// The AO pass's defines (gtao.comp, ao_denoise.comp): the settings table's SettingPass::Ao rows.
std::vector<KeyDefine> aoDefines(const VariantKey& key, const Scene& scene);
// Tone map pass: the output transform's settings.
std::vector<KeyDefine> toneMapDefines(const VariantKey& key, const Scene& scene);

}  // namespace hv::render

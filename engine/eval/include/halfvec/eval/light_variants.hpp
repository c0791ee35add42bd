// The compilations of the engine's light code (shaders/common/lights.glsl as C++) that the CPU
// evaluation runs: the options as a struct compared field by field, and ONE list of the compiled
// combinations, kEngineLightVariants, from which everything else is generated: the build compiles
// lights.glsl once per entry (tools/light_variants_gen.cpp writes the defines of each,
// engine_lights.cpp includes them), compiledLightVariant() finds an entry at compile time (a
// combination that is not in the list does not compile) and findLightVariant() at run time (an
// error naming the fields and values that no entry has).
//
// Adding a variant: one entry in kEngineLightVariants. Adding an option: one row in
// HV_ENGINE_LIGHT_OPTIONS (its define, and which term reads it).
//
// This header includes nothing but the settings' enums: the generator tool compiles it alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>

#include "halfvec/scene/render_settings.hpp"

namespace hv::eval {

// The term of the light code a variant returns: HV_DIRECT_TERMS 1 (diffuse) or 2 (specular).
enum class LightTerm : uint8_t { Diffuse, Specular };

// Which variants an option changes code in: the diffuse term's, the specular term's, or the
// specular term's only where a light mode is an LTC (HV_LTC_V_RATIO scales the LTC's magnitude;
// lights.glsl never reads it otherwise). An option a term does not read is left at its default
// in the list, and a request's value for it matches any entry (canonicalLightOptions).
enum class ReadBy : uint8_t { Diffuse, Specular, SpecularLtc };

// X(TYPE, MEMBER, DEFAULT, DEFINE, READ_BY): one row per option of the light code that the
// evaluation varies. MEMBER is the RenderSettings member of the same name where there is one (the
// same enum); DEFINE is the lights.glsl define it sets (a bare name; its value: the enum's value,
// 1/0 for a bool); DEFAULT is the engine's. Every other define keeps the engine's default, except
// the physical falloff (HV_FALLOFF_PLUS_ONE 0) and HV_DIRECT_TERMS (the variant's term).
// clang-format off
#define HV_ENGINE_LIGHT_OPTIONS(X)                                                                 \
  X(SphereDiffuse, sphere_diffuse, SphereDiffuse::KarisPoint, HV_SPHERE_DIFFUSE, ReadBy::Diffuse)  \
  X(bool, sphere_normalization, true, HV_SPHERE_NORMALIZATION, ReadBy::Specular)                   \
  X(SphereSpecular, sphere_specular, SphereSpecular::RepresentativePoint, HV_SPHERE_SPECULAR,      \
    ReadBy::Specular)                                                                              \
  X(TubeSpecular, tube_specular, TubeSpecular::ClosestPointEq19, HV_TUBE_SPECULAR,                 \
    ReadBy::Specular)                                                                              \
  X(bool, tube_normalization, true, HV_TUBE_NORMALIZATION, ReadBy::Specular)                       \
  X(TubeDiffuse, tube_diffuse, TubeDiffuse::KarisEq16, HV_TUBE_DIFFUSE, ReadBy::Diffuse)           \
  X(DistributionTerm, d, DistributionTerm::GGX, HV_BRDF_D, ReadBy::Specular)                       \
  X(VisibilityTerm, v, VisibilityTerm::SchlickGGX, HV_BRDF_V, ReadBy::Specular)                    \
  /* lights.glsl HV_LTC_V_RATIO: no RenderSettings member, the engine always scales */             \
  X(bool, ltc_v_ratio, true, HV_LTC_V_RATIO, ReadBy::SpecularLtc)
// clang-format on

// The light options of RenderSettings that change the engine's sphere/tube formulas, and the
// BRDF terms the engine and the reference both use (the LTC modes are fitted to GGX D and
// height-correlated Smith V; docs/lights.md, "Other BRDF choices").
struct EngineLightOptions {
#define HV_LIGHT_OPTION_MEMBER(TYPE, MEMBER, DEFAULT, DEFINE, READ_BY) TYPE MEMBER = DEFAULT;
  HV_ENGINE_LIGHT_OPTIONS(HV_LIGHT_OPTION_MEMBER)
#undef HV_LIGHT_OPTION_MEMBER
  bool operator==(const EngineLightOptions&) const = default;
};

// Whether the variants of `term` read an option read by `r`, given the other options `o`.
constexpr bool lightTermReads(LightTerm term, ReadBy r, const EngineLightOptions& o) {
  switch (r) {
    case ReadBy::Diffuse:
      return term == LightTerm::Diffuse;
    case ReadBy::Specular:
      return term == LightTerm::Specular;
    case ReadBy::SpecularLtc:
      return term == LightTerm::Specular &&
             (o.sphere_specular == SphereSpecular::Ltc || o.tube_specular == TubeSpecular::Ltc);
  }
  return false;
}

// `o` with every option that `term` does not read reset to its default: requests that differ only
// in such options have the same canonical options, and find the same entry.
constexpr EngineLightOptions canonicalLightOptions(LightTerm term, const EngineLightOptions& o) {
  EngineLightOptions c;
#define HV_LIGHT_OPTION_KEEP(TYPE, MEMBER, DEFAULT, DEFINE, READ_BY) \
  if (lightTermReads(term, READ_BY, o)) c.MEMBER = o.MEMBER;
  HV_ENGINE_LIGHT_OPTIONS(HV_LIGHT_OPTION_KEEP)
#undef HV_LIGHT_OPTION_KEEP
  return c;
}

// One compilation of the light code: its term and its options (canonical).
struct LightVariant {
  LightTerm term = LightTerm::Diffuse;
  EngineLightOptions options;
  bool operator==(const LightVariant&) const = default;
};

// The list of compiled variants. What the evaluation requests (the accuracy sweeps' methods,
// light_accuracy.cpp; the tests) must be here; the rest of the options stay at the defaults.
inline constexpr LightVariant kEngineLightVariants[] = {
    // Diffuse: both sphere modes x both tube modes.
    {LightTerm::Diffuse, {}},
    {LightTerm::Diffuse, {.tube_diffuse = TubeDiffuse::Ltc}},
    {LightTerm::Diffuse, {.sphere_diffuse = SphereDiffuse::HorizonCorrect}},
    {LightTerm::Diffuse,
     {.sphere_diffuse = SphereDiffuse::HorizonCorrect, .tube_diffuse = TubeDiffuse::Ltc}},
    // Specular, representative point: both normalizations x tube eq. 19 / eq. 18.
    {LightTerm::Specular, {.sphere_normalization = false, .tube_normalization = false}},
    {LightTerm::Specular, {.sphere_normalization = false}},
    {LightTerm::Specular,
     {.sphere_normalization = false,
      .tube_specular = TubeSpecular::SmallestAngleEq18,
      .tube_normalization = false}},
    {LightTerm::Specular,
     {.sphere_normalization = false, .tube_specular = TubeSpecular::SmallestAngleEq18}},
    {LightTerm::Specular, {.tube_normalization = false}},
    {LightTerm::Specular, {}},
    {LightTerm::Specular,
     {.tube_specular = TubeSpecular::SmallestAngleEq18, .tube_normalization = false}},
    {LightTerm::Specular, {.tube_specular = TubeSpecular::SmallestAngleEq18}},
    // Specular, LTC (sphere and tube): with the fitted lobe's V, with Schlick-GGX V with and
    // without the V ratio, and with Beckmann D.
    {LightTerm::Specular,
     {.sphere_specular = SphereSpecular::Ltc,
      .tube_specular = TubeSpecular::Ltc,
      .v = VisibilityTerm::SmithGGXCorrelated}},
    {LightTerm::Specular,
     {.sphere_specular = SphereSpecular::Ltc, .tube_specular = TubeSpecular::Ltc}},
    {LightTerm::Specular,
     {.sphere_specular = SphereSpecular::Ltc,
      .tube_specular = TubeSpecular::Ltc,
      .ltc_v_ratio = false}},
    {LightTerm::Specular,
     {.sphere_specular = SphereSpecular::Ltc,
      .tube_specular = TubeSpecular::Ltc,
      .d = DistributionTerm::Beckmann}},
    // Specular, representative point with the LTC's lobe (height-correlated Smith V).
    {LightTerm::Specular, {.v = VisibilityTerm::SmithGGXCorrelated}},
};
inline constexpr size_t kEngineLightVariantCount = std::size(kEngineLightVariants);

namespace light_variants_detail {
consteval bool lightVariantsCanonicalAndDistinct() {
  for (size_t i = 0; i < kEngineLightVariantCount; ++i) {
    const LightVariant& v = kEngineLightVariants[i];
    if (canonicalLightOptions(v.term, v.options) != v.options) return false;
    for (size_t j = 0; j < i; ++j) {
      if (kEngineLightVariants[j] == v) return false;
    }
  }
  return true;
}
// Not constexpr, and never defined: a constant evaluation that reaches the call fails with its
// name in the compiler's message.
void no_compiled_light_variant_has_these_options_see_kEngineLightVariants();
}  // namespace light_variants_detail
static_assert(light_variants_detail::lightVariantsCanonicalAndDistinct(),
              "kEngineLightVariants: an entry sets an option its term does not read (it compiles "
              "the same code as the default), or two entries are the same");

// An entry of kEngineLightVariants, found by compiledLightVariant (at compile time) or
// findLightVariant (at run time, light_accuracy.hpp).
struct CompiledLightVariant {
  uint8_t index = 0;
  constexpr const LightVariant& variant() const { return kEngineLightVariants[index]; }
  bool operator==(const CompiledLightVariant&) const = default;
};
static_assert(kEngineLightVariantCount <= 256, "CompiledLightVariant::index is 8 bits");

// The index of the entry that runs `term` with options `o`, or kEngineLightVariantCount.
constexpr size_t lightVariantIndex(LightTerm term, const EngineLightOptions& o) {
  const LightVariant want{term, canonicalLightOptions(term, o)};
  for (size_t i = 0; i < kEngineLightVariantCount; ++i) {
    if (kEngineLightVariants[i] == want) return i;
  }
  return kEngineLightVariantCount;
}

// The compiled variant for a request known at compile time: a combination that is not in
// kEngineLightVariants is a compile error (naming the function above).
consteval CompiledLightVariant compiledLightVariant(LightTerm term, const EngineLightOptions& o) {
  const size_t i = lightVariantIndex(term, o);
  if (i == kEngineLightVariantCount) {
    light_variants_detail::no_compiled_light_variant_has_these_options_see_kEngineLightVariants();
  }
  return CompiledLightVariant{uint8_t(i)};
}

}  // namespace hv::eval

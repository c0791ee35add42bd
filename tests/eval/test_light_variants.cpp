// The compiled variants of the engine's light code (halfvec/eval/light_variants.hpp): the list,
// the lookup by options compared field by field, the run-time error for a combination that is not
// compiled, and that every request of the accuracy sweeps is compiled. (A request known at compile
// time that is not compiled fails to build: tests/eval/compile, run by CTest.)
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "halfvec/eval/light_accuracy.hpp"

using namespace hv;
using namespace hv::eval;

namespace {

// Compile-time lookups: the default options are the first entry of each term, and a request's
// options that its term does not read match any value.
static_assert(compiledLightVariant(LightTerm::Diffuse, {}).index == 0);
static_assert(compiledLightVariant(LightTerm::Diffuse, {}) ==
              compiledLightVariant(LightTerm::Diffuse, {.sphere_specular = SphereSpecular::Ltc,
                                                        .v = VisibilityTerm::Implicit}));
static_assert(kEngineLightVariants[compiledLightVariant(LightTerm::Specular, {}).index].term ==
              LightTerm::Specular);

Light testLight(LightType type) {
  Light l;
  l.type = type;
  l.position = glm::normalize(glm::vec3(0.9f, 0.1f, 0.15f));
  l.radius = 0.4f;
  l.length = 1.0f;
  l.axis = glm::vec3(0.0f, 1.0f, 0.0f);
  l.range = 1e4f;
  return l;
}

// The engine's term over a few views for a light that straddles the horizon (radius 0.4 at
// distance 1, center 9 degrees up: where the sphere-diffuse modes differ).
std::vector<float> values(const EngineLightOptions& o, LightTerm term, LightType type) {
  const glm::vec3 P(0.0f), N(0.0f, 0.0f, 1.0f);
  std::vector<float> v;
  for (glm::vec3 V :
       {glm::vec3(-0.8f, -0.2f, 0.6f), glm::vec3(0.0f, 0.6f, 0.8f), glm::vec3(0.3f, -0.3f, 0.9f)}) {
    v.push_back(engineLightTerm(o, term, testLight(type), P, N, glm::normalize(V), glm::vec3(1.0f),
                                term == LightTerm::Diffuse ? 0.0f : 1.0f, 0.3f)
                    .x);
  }
  return v;
}

// Every method the accuracy sweeps evaluate (sweepSphere, sweepTube: the diffuse lists with the
// diffuse term, the specular lists with the specular term; the sweeps call engineLightTerm with
// LightMethod::variant) is in the list, as the run-time lookup of its options finds it.
TEST(LightVariants, EveryMethodOfTheSweepsIsCompiled) {
  int n = 0;
  for (const auto* list : {&sphereDiffuseMethods(), &tubeDiffuseMethods()}) {
    for (const LightMethod& m : *list) {
      EXPECT_EQ(m.variant.variant().term, LightTerm::Diffuse) << m.name;
      EXPECT_EQ(findLightVariant(LightTerm::Diffuse, m.o), m.variant) << m.name;
      ++n;
    }
  }
  for (const auto* list : {&sphereSpecularMethods(), &tubeSpecularMethods()}) {
    for (const LightMethod& m : *list) {
      EXPECT_EQ(m.variant.variant().term, LightTerm::Specular) << m.name;
      EXPECT_EQ(findLightVariant(LightTerm::Specular, m.o), m.variant) << m.name;
      ++n;
    }
  }
  EXPECT_EQ(n, int(kSphereDiffuseMethods) + int(kTubeDiffuseMethods) + int(kSphereSpecularMethods) +
                   int(kTubeSpecularMethods));
}

// Each entry is found by its own options, and only by them (the list holds no two entries that
// compare equal field by field).
TEST(LightVariants, EachEntryIsFoundByItsOptions) {
  for (size_t i = 0; i < kEngineLightVariantCount; ++i) {
    const LightVariant& v = kEngineLightVariants[i];
    EXPECT_EQ(findLightVariant(v.term, v.options).index, i);
  }
}

constexpr EngineLightOptions kLtc{.sphere_specular = SphereSpecular::Ltc,
                                  .tube_specular = TubeSpecular::Ltc};

// The options a term does not read do not change what it runs: the diffuse term with any
// specular option, the representative point without the LTC's V ratio (bit-identical values).
TEST(LightVariants, OptionsATermDoesNotReadMatchAnyValue) {
  const EngineLightOptions spec{.sphere_normalization = false,
                                .sphere_specular = SphereSpecular::Ltc,
                                .v = VisibilityTerm::Implicit};
  EXPECT_EQ(findLightVariant(LightTerm::Diffuse, spec), findLightVariant(LightTerm::Diffuse, {}));
  EXPECT_EQ(values(spec, LightTerm::Diffuse, LightType::Sphere),
            values({}, LightTerm::Diffuse, LightType::Sphere));
  EXPECT_EQ(findLightVariant(LightTerm::Specular, {.ltc_v_ratio = false}),
            findLightVariant(LightTerm::Specular, {}));
  EngineLightOptions no_ratio = kLtc;
  no_ratio.ltc_v_ratio = false;
  EXPECT_NE(findLightVariant(LightTerm::Specular, no_ratio),
            findLightVariant(LightTerm::Specular, kLtc));
}

// Each option reaches its compilation: an entry that differs from the default in one option
// shades the lights that read it differently and the others bit-identically (a define the
// generated file did not set would give the default's values for both).
TEST(LightVariants, EachOptionChangesTheLightsThatReadIt) {
  using LT = LightType;
  const LightTerm D = LightTerm::Diffuse, S = LightTerm::Specular;
  const EngineLightOptions horizon{.sphere_diffuse = SphereDiffuse::HorizonCorrect};
  EXPECT_NE(values(horizon, D, LT::Sphere), values({}, D, LT::Sphere));
  EXPECT_EQ(values(horizon, D, LT::Tube), values({}, D, LT::Tube));
  const EngineLightOptions tube_ltc{.tube_diffuse = TubeDiffuse::Ltc};
  EXPECT_NE(values(tube_ltc, D, LT::Tube), values({}, D, LT::Tube));
  EXPECT_EQ(values(tube_ltc, D, LT::Sphere), values({}, D, LT::Sphere));
  const EngineLightOptions sphere_plain{.sphere_normalization = false};
  EXPECT_NE(values(sphere_plain, S, LT::Sphere), values({}, S, LT::Sphere));
  const EngineLightOptions tube_plain{.tube_normalization = false};
  EXPECT_NE(values(tube_plain, S, LT::Tube), values({}, S, LT::Tube));
  EXPECT_EQ(values(tube_plain, S, LT::Sphere), values({}, S, LT::Sphere));
  const EngineLightOptions eq18{.tube_specular = TubeSpecular::SmallestAngleEq18};
  EXPECT_NE(values(eq18, S, LT::Tube), values({}, S, LT::Tube));
  EXPECT_EQ(values(eq18, S, LT::Sphere), values({}, S, LT::Sphere));
  const EngineLightOptions smith{.v = VisibilityTerm::SmithGGXCorrelated};
  EXPECT_NE(values(smith, S, LT::Sphere), values({}, S, LT::Sphere));
  EXPECT_NE(values(kLtc, S, LT::Sphere), values({}, S, LT::Sphere));
  EXPECT_NE(values(kLtc, S, LT::Tube), values({}, S, LT::Tube));
  EngineLightOptions no_ratio = kLtc;
  no_ratio.ltc_v_ratio = false;
  EXPECT_NE(values(no_ratio, S, LT::Sphere), values(kLtc, S, LT::Sphere));
}

// A combination chosen at run time that is not compiled: std::invalid_argument naming the term,
// the requested options that are not the defaults, and how the nearest entry differs.
TEST(LightVariants, MissingCombinationNamesTheFieldsAndValues) {
  EngineLightOptions o = kLtc;
  o.v = VisibilityTerm::Implicit;
  try {
    findLightVariant(LightTerm::Specular, o);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    std::printf("%s\n", msg.c_str());
    EXPECT_NE(msg.find("no compiled specular variant"), std::string::npos) << msg;
    EXPECT_NE(msg.find("sphere_specular=ltc, tube_specular=ltc, v=implicit"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("differs in v=implicit (compiled: "), std::string::npos) << msg;
    EXPECT_NE(msg.find("kEngineLightVariants"), std::string::npos) << msg;
  }
  o = {.sphere_diffuse = SphereDiffuse::HorizonCorrect, .tube_normalization = false};
  EXPECT_NO_THROW(findLightVariant(LightTerm::Specular, o));  // sphere_diffuse: not read
  o.sphere_specular = SphereSpecular::Ltc;                    // LTC entries: normalized tube
  EXPECT_THROW(findLightVariant(LightTerm::Specular, o), std::invalid_argument);
  EXPECT_THROW(engineLightTerm(o, LightTerm::Specular, testLight(LightType::Tube), glm::vec3(0.0f),
                               glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(1.0f), 1.0f, 0.5f),
               std::invalid_argument);
}

}  // namespace

// The engine's light formulas (shaders/common/lights.glsl, compiled as C++) for every entry of
// kEngineLightVariants (halfvec/eval/light_variants.hpp), each term on its own (HV_DIRECT_TERMS),
// with the physical falloff. The build generates one block of defines per entry
// (tools/light_variants_gen.cpp), each followed by light_variant.inc: one more compilation of the
// shared headers in a namespace of its own.
#include "halfvec/eval/light_accuracy.hpp"

#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "halfvec/scene/enums.hpp"
#include "halfvec/shading/light_gpu.hpp"
#include "light_variants_generated.inc"

namespace hv::eval {

namespace {

using EvalFn = glm::vec3 (*)(const hv::GpuLight&, const glm::vec3&, const glm::vec3&,
                             const glm::vec3&, const glm::vec3&, float, float);
constexpr EvalFn kEval[] = {HV_ENGINE_LIGHT_VARIANT_EVALS};
static_assert(std::size(kEval) == kEngineLightVariantCount,
              "light_variants_generated.inc is not kEngineLightVariants");

std::string valueName(bool b) {
  return b ? "true" : "false";
}
template <class E>
std::string valueName(E e) {
  return std::string(toString(e));
}

const char* termName(LightTerm t) {
  return t == LightTerm::Diffuse ? "diffuse" : "specular";
}

// "name=value" for each option of `o` that differs from `base`, comma-separated; with
// base_name, each followed by base's value.
std::string differingOptions(const EngineLightOptions& o, const EngineLightOptions& base,
                             const char* base_name) {
  std::ostringstream s;
  const char* sep = "";
#define HV_LIGHT_OPTION_DIFF(TYPE, MEMBER, DEFAULT, DEFINE, READ_BY)                \
  if (o.MEMBER != base.MEMBER) {                                                    \
    s << sep << #MEMBER "=" << valueName(o.MEMBER);                                 \
    if (base_name) s << " (" << base_name << ": " << valueName(base.MEMBER) << ")"; \
    sep = ", ";                                                                     \
  }
  HV_ENGINE_LIGHT_OPTIONS(HV_LIGHT_OPTION_DIFF)
#undef HV_LIGHT_OPTION_DIFF
  return s.str();
}

int differingCount(const EngineLightOptions& a, const EngineLightOptions& b) {
  int n = 0;
#define HV_LIGHT_OPTION_COUNT(TYPE, MEMBER, DEFAULT, DEFINE, READ_BY) n += a.MEMBER != b.MEMBER;
  HV_ENGINE_LIGHT_OPTIONS(HV_LIGHT_OPTION_COUNT)
#undef HV_LIGHT_OPTION_COUNT
  return n;
}

}  // namespace

CompiledLightVariant findLightVariant(LightTerm term, const EngineLightOptions& o) {
  const size_t i = lightVariantIndex(term, o);
  if (i < kEngineLightVariantCount) return CompiledLightVariant{uint8_t(i)};
  // Name what is missing: the request's options that the term reads and that are not the
  // defaults, and the fields in which the nearest entry of the same term differs.
  const EngineLightOptions want = canonicalLightOptions(term, o);
  const LightVariant* nearest = nullptr;
  int nearest_n = 0;
  for (const LightVariant& v : kEngineLightVariants) {
    if (v.term != term) continue;
    const int n = differingCount(want, v.options);
    if (!nearest || n < nearest_n) nearest = &v, nearest_n = n;
  }
  std::ostringstream msg;
  const std::string set = differingOptions(want, EngineLightOptions{}, nullptr);
  msg << "no compiled " << termName(term) << " variant of the engine's light code with "
      << (set.empty() ? std::string("the default options") : set);
  if (nearest) {
    msg << "; the nearest compiled one differs in "
        << differingOptions(want, nearest->options, "compiled");
  }
  msg << "; add the combination to kEngineLightVariants (halfvec/eval/light_variants.hpp)";
  throw std::invalid_argument(msg.str());
}

glm::vec3 engineLightTerm(CompiledLightVariant variant, const Light& light, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const glm::vec3& base_color,
                          float metallic, float roughness) {
  return kEval[variant.index](packLight(light), P, N, V, base_color, metallic, roughness);
}

glm::vec3 engineLightTerm(const EngineLightOptions& o, LightTerm term, const Light& light,
                          const glm::vec3& P, const glm::vec3& N, const glm::vec3& V,
                          const glm::vec3& base_color, float metallic, float roughness) {
  return engineLightTerm(findLightVariant(term, o), light, P, N, V, base_color, metallic,
                         roughness);
}

}  // namespace hv::eval

// The engine's light formulas (shaders/common/lights.glsl, compiled as C++) for every option the
// accuracy sweep compares, each term on its own (HV_DIRECT_TERMS), with the physical falloff.
// Each block compiles the shared headers once more with other defines (light_variant.inc).
#include "halfvec/eval/light_accuracy.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "halfvec/shading/light_gpu.hpp"
#define HV_VARIANT_NS diffuse_sd0_td0
#define HV_VARIANT_TERMS 1
#define HV_VARIANT_SD 0
#define HV_VARIANT_TD 0
#include "light_variant.inc"
#define HV_VARIANT_NS diffuse_sd0_td1
#define HV_VARIANT_TERMS 1
#define HV_VARIANT_SD 0
#define HV_VARIANT_TD 1
#include "light_variant.inc"
#define HV_VARIANT_NS diffuse_sd1_td0
#define HV_VARIANT_TERMS 1
#define HV_VARIANT_SD 1
#define HV_VARIANT_TD 0
#include "light_variant.inc"
#define HV_VARIANT_NS diffuse_sd1_td1
#define HV_VARIANT_TERMS 1
#define HV_VARIANT_SD 1
#define HV_VARIANT_TD 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts0_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts0_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts1_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts1_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts0_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts0_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts1_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts1_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_ltc_vsmith
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SS 1
#define HV_VARIANT_TS 2
#define HV_VARIANT_V 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_ltc_vschlick
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SS 1
#define HV_VARIANT_TS 2
#define HV_VARIANT_V 0
#define HV_VARIANT_VR 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_ltc_vschlick_noratio
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SS 1
#define HV_VARIANT_TS 2
#define HV_VARIANT_V 0
#define HV_VARIANT_VR 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_ltc_dbeckmann
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SS 1
#define HV_VARIANT_TS 2
#define HV_VARIANT_D 1
#define HV_VARIANT_V 0
#define HV_VARIANT_VR 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_rp_vsmith
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_V 1
#include "light_variant.inc"

namespace hv::eval {

namespace {

namespace d = reference_detail;

using EvalFn = glm::vec3 (*)(const hv::GpuLight&, const glm::vec3&, const glm::vec3&,
                             const glm::vec3&, const glm::vec3&, float, float);
struct Variant {
  const int* options;  // terms, sd, sn, ss, ts, tn, td, d, v, vr (light_variant.inc kOptions)
  EvalFn eval;
};
const Variant kVariants[] = {
    {d::diffuse_sd0_td0::kOptions, d::diffuse_sd0_td0::eval},
    {d::diffuse_sd0_td1::kOptions, d::diffuse_sd0_td1::eval},
    {d::diffuse_sd1_td0::kOptions, d::diffuse_sd1_td0::eval},
    {d::diffuse_sd1_td1::kOptions, d::diffuse_sd1_td1::eval},
    {d::specular_sn0_ts0_tn0::kOptions, d::specular_sn0_ts0_tn0::eval},
    {d::specular_sn0_ts0_tn1::kOptions, d::specular_sn0_ts0_tn1::eval},
    {d::specular_sn0_ts1_tn0::kOptions, d::specular_sn0_ts1_tn0::eval},
    {d::specular_sn0_ts1_tn1::kOptions, d::specular_sn0_ts1_tn1::eval},
    {d::specular_sn1_ts0_tn0::kOptions, d::specular_sn1_ts0_tn0::eval},
    {d::specular_sn1_ts0_tn1::kOptions, d::specular_sn1_ts0_tn1::eval},
    {d::specular_sn1_ts1_tn0::kOptions, d::specular_sn1_ts1_tn0::eval},
    {d::specular_sn1_ts1_tn1::kOptions, d::specular_sn1_ts1_tn1::eval},
    {d::specular_ltc_vsmith::kOptions, d::specular_ltc_vsmith::eval},
    {d::specular_ltc_vschlick::kOptions, d::specular_ltc_vschlick::eval},
    {d::specular_ltc_vschlick_noratio::kOptions, d::specular_ltc_vschlick_noratio::eval},
    {d::specular_ltc_dbeckmann::kOptions, d::specular_ltc_dbeckmann::eval},
    {d::specular_rp_vsmith::kOptions, d::specular_rp_vsmith::eval}};

}  // namespace

std::vector<EngineLightOptions> compiledLightVariants(LightTerm term) {
  std::vector<EngineLightOptions> out;
  for (const Variant& v : kVariants) {
    if (v.options[0] != (term == LightTerm::Diffuse ? 1 : 2)) continue;
    EngineLightOptions o;
    o.sphere_diffuse = SphereDiffuse(v.options[1]);
    o.sphere_normalization = v.options[2] != 0;
    o.sphere_specular = SphereSpecular(v.options[3]);
    o.tube_specular = TubeSpecular(v.options[4]);
    o.tube_normalization = v.options[5] != 0;
    o.tube_diffuse = TubeDiffuse(v.options[6]);
    o.d = DistributionTerm(v.options[7]);
    o.v = VisibilityTerm(v.options[8]);
    o.ltc_v_ratio = v.options[9] != 0;
    out.push_back(o);
  }
  return out;
}

glm::vec3 engineLightTerm(const EngineLightOptions& o, LightTerm term, const Light& light,
                          const glm::vec3& P, const glm::vec3& N, const glm::vec3& V,
                          const glm::vec3& base_color, float metallic, float roughness) {
  // Options a term does not read match any compiled value: the diffuse term reads the diffuse
  // modes only, the specular term the specular ones and the BRDF terms.
  const bool diffuse = term == LightTerm::Diffuse;
  const int want[] = {diffuse ? 1 : 2,
                      int(o.sphere_diffuse),
                      int(o.sphere_normalization),
                      int(o.sphere_specular),
                      int(o.tube_specular),
                      int(o.tube_normalization),
                      int(o.tube_diffuse),
                      int(o.d),
                      int(o.v),
                      int(o.ltc_v_ratio)};
  const bool ltc = o.sphere_specular == SphereSpecular::Ltc || o.tube_specular == TubeSpecular::Ltc;
  const bool used[] = {true,     diffuse, !diffuse, !diffuse, !diffuse,
                       !diffuse, diffuse, !diffuse, !diffuse, !diffuse && ltc};
  for (const Variant& v : kVariants) {
    bool match = true;
    for (size_t k = 0; k < std::size(want) && match; ++k) {
      match = !used[k] || v.options[k] == want[k];
    }
    if (match) return v.eval(packLight(light), P, N, V, base_color, metallic, roughness);
  }
  throw std::logic_error("engineLightTerm: no compiled variant for these options");
}

}  // namespace hv::eval

// The engine's light formulas (shaders/common/lights.glsl, compiled as C++) for every option the
// accuracy sweep compares, each term on its own (HV_DIRECT_TERMS), with the physical falloff.
// Each block compiles the shared headers once more with other defines (light_variant.inc).
#include "halfvec/eval/light_accuracy.hpp"

#include <stdexcept>

#include "halfvec/shading/light_gpu.hpp"
#define HV_VARIANT_NS diffuse_sd0
#define HV_VARIANT_TERMS 1
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS diffuse_sd1
#define HV_VARIANT_TERMS 1
#define HV_VARIANT_SD 1
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts0_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts0_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts1_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn0_ts1_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 0
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts0_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts0_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 0
#define HV_VARIANT_TN 1
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts1_tn0
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 0
#include "light_variant.inc"
#define HV_VARIANT_NS specular_sn1_ts1_tn1
#define HV_VARIANT_TERMS 2
#define HV_VARIANT_SD 0
#define HV_VARIANT_SN 1
#define HV_VARIANT_TS 1
#define HV_VARIANT_TN 1
#include "light_variant.inc"

namespace hv::eval {

glm::vec3 engineLightTerm(const EngineLightOptions& o, LightTerm term, const Light& light,
                          const glm::vec3& P, const glm::vec3& N, const glm::vec3& V,
                          const glm::vec3& base_color, float metallic, float roughness) {
  namespace d = reference_detail;
  const GpuLight g = packLight(light);
  if (term == LightTerm::Diffuse) {
    return o.sphere_diffuse == SphereDiffuse::HorizonCorrect
               ? d::diffuse_sd1::eval(g, P, N, V, base_color, metallic, roughness)
               : d::diffuse_sd0::eval(g, P, N, V, base_color, metallic, roughness);
  }
  const int key = (o.sphere_normalization ? 4 : 0) +
                  (o.tube_specular == TubeSpecular::SmallestAngleEq18 ? 2 : 0) +
                  (o.tube_normalization ? 1 : 0);
  switch (key) {
    case 0:
      return d::specular_sn0_ts0_tn0::eval(g, P, N, V, base_color, metallic, roughness);
    case 1:
      return d::specular_sn0_ts0_tn1::eval(g, P, N, V, base_color, metallic, roughness);
    case 2:
      return d::specular_sn0_ts1_tn0::eval(g, P, N, V, base_color, metallic, roughness);
    case 3:
      return d::specular_sn0_ts1_tn1::eval(g, P, N, V, base_color, metallic, roughness);
    case 4:
      return d::specular_sn1_ts0_tn0::eval(g, P, N, V, base_color, metallic, roughness);
    case 5:
      return d::specular_sn1_ts0_tn1::eval(g, P, N, V, base_color, metallic, roughness);
    case 6:
      return d::specular_sn1_ts1_tn0::eval(g, P, N, V, base_color, metallic, roughness);
    case 7:
      return d::specular_sn1_ts1_tn1::eval(g, P, N, V, base_color, metallic, roughness);
  }
  throw std::logic_error("engineLightTerm: bad option key");
}

}  // namespace hv::eval

#include "halfvec/shading/brdf.hpp"

namespace hv {

namespace g = hv::glsl;

BrdfConfig BrdfConfig::fromSettings(const RenderSettings& s) {
  BrdfConfig c;
  c.d = s.d;
  c.v = s.v;
  c.f = s.f;
  c.diffuse = s.diffuse;
  c.remap_roughness = s.remap_roughness;
  return c;
}

float evalD(const BrdfConfig& c, float alpha, float NoH, float sin2_NH) {
  switch (c.d) {
    case DistributionTerm::GGX:
      return g::D_GGX(alpha, NoH, sin2_NH);
    case DistributionTerm::Beckmann:
      return g::D_Beckmann(alpha, NoH, sin2_NH);
    case DistributionTerm::BlinnPhong:
      return g::D_BlinnPhong(alpha, NoH, sin2_NH);
  }
  return 0.0f;
}

float evalD(const BrdfConfig& c, float alpha, float NoH) {
  return evalD(c, alpha, NoH, (1.0f - NoH) * (1.0f + NoH));
}

float evalVForAlpha(const BrdfConfig& c, float alpha, float NoV, float NoL, float NoH, float VoH) {
  switch (c.v) {
    case VisibilityTerm::SchlickGGX:
      return g::V_SchlickGGX(0.5f * alpha, NoV, NoL);
    case VisibilityTerm::SmithGGXCorrelated:
      return g::V_SmithGGXCorrelated(alpha, NoV, NoL);
    case VisibilityTerm::SmithGGXCorrelatedFast:
      return g::V_SmithGGXCorrelatedFast(alpha, NoV, NoL);
    case VisibilityTerm::SmithGGXSeparable:
      return g::V_SmithGGXSeparable(alpha, NoV, NoL);
    case VisibilityTerm::SmithBeckmannSeparable:
      return g::V_SmithBeckmannSeparable(alpha, NoV, NoL);
    case VisibilityTerm::CookTorrance:
      return g::V_CookTorrance(NoH, NoV, NoL, VoH);
    case VisibilityTerm::Implicit:
      return g::V_Implicit();
  }
  return 0.0f;
}

float evalV(const BrdfConfig& c, float roughness, float alpha, float NoV, float NoL, float NoH,
            float VoH) {
  // Karis 2013 eq. 4: the rule of brdf.glsl's visibility().
  const bool remap = g::remapAppliesTo(c.remap_roughness, static_cast<int>(c.v));
  float alpha_v = remap ? g::remappedVisibilityAlpha(roughness) : alpha;
  return evalVForAlpha(c, alpha_v, NoV, NoL, NoH, VoH);
}

glm::vec3 evalF(const BrdfConfig& c, const glm::vec3& f0, float VoH) {
  switch (c.f) {
    case FresnelTerm::SchlickPow5:
      return g::F_Schlick(f0, 1.0f, VoH);
    case FresnelTerm::SchlickSG:
      return g::F_SchlickSG(f0, 1.0f, VoH);
    case FresnelTerm::Exact:
      return g::F_ExactDielectric(f0, VoH);
    case FresnelTerm::SchlickF90Occlusion:
      return g::F_SchlickF90Occlusion(f0, VoH);
  }
  return glm::vec3(0.0f);
}

float evalFd(const BrdfConfig& c, float roughness, float NoV, float NoL, float LoH) {
  switch (c.diffuse) {
    case DiffuseTerm::Lambert:
      return g::Fd_Lambert();
    case DiffuseTerm::Burley:
      return g::Fd_Burley(roughness, NoV, NoL, LoH);
  }
  return 0.0f;
}

std::vector<std::pair<std::string, std::string>> brdfDefines(const RenderSettings& s) {
  // The light pass's rows of the settings table (render_settings.hpp), whose enum values are
  // setting_values.glsl's, and the term mask.
  auto out = settingDefines(s, SettingPass::Light);
  out.emplace_back("HV_DIRECT_TERMS", std::to_string(int(s.direct_terms)));
  return out;
}

}  // namespace hv

// GENERATED from the value lists of engine/scene/include/halfvec/scene/render_settings.hpp
// (HV_SETTING_ENUM) by settingValuesGlsl(): do not edit; regenerate with
//   build/shaders/hv_setting_values --out shaders/common/setting_values.glsl
// The number of every value of an enumerated render setting that reaches a shader as a
// define, for GLSL and C++ alike: the shaders compare HV_BRDF_D and the other defines against
// these names, and the C++ enum's value is the same position in the same list. What each
// value means is said at its list.
#ifndef HV_SETTING_VALUES_GLSL
#define HV_SETTING_VALUES_GLSL

// tone_map (HV_TONEMAP): reinhard, reinhard_luminance, none, pbr_neutral, aces
#define HV_TONEMAP_REINHARD 0
#define HV_TONEMAP_REINHARD_LUMINANCE 1
#define HV_TONEMAP_NONE 2
#define HV_TONEMAP_PBR_NEUTRAL 3
#define HV_TONEMAP_ACES 4

// gamma (HV_GAMMA): gamma22, srgb
#define HV_GAMMA_22 0
#define HV_GAMMA_SRGB 1

// brdf.d (HV_BRDF_D): ggx, beckmann, blinn_phong
#define HV_D_GGX 0
#define HV_D_BECKMANN 1
#define HV_D_BLINN_PHONG 2

// brdf.v (HV_BRDF_V): schlick_ggx, smith_ggx_correlated, smith_ggx_correlated_fast,
// smith_ggx_separable, smith_beckmann_separable, cook_torrance, implicit
#define HV_V_SCHLICK_GGX 0
#define HV_V_SMITH_GGX_CORRELATED 1
#define HV_V_SMITH_GGX_CORRELATED_FAST 2
#define HV_V_SMITH_GGX_SEPARABLE 3
#define HV_V_SMITH_BECKMANN_SEPARABLE 4
#define HV_V_COOK_TORRANCE 5
#define HV_V_IMPLICIT 6

// brdf.f (HV_BRDF_F): schlick_pow5, schlick_sg, exact, schlick_f90_occlusion
#define HV_F_SCHLICK 0
#define HV_F_SCHLICK_SG 1
#define HV_F_EXACT 2
#define HV_F_SCHLICK_F90_OCCLUSION 3

// brdf.diffuse (HV_BRDF_FD): lambert, burley
#define HV_FD_LAMBERT 0
#define HV_FD_BURLEY 1

// sphere_diffuse (HV_SPHERE_DIFFUSE): karis_point, horizon_correct
#define HV_SPHERE_DIFFUSE_KARIS_POINT 0
#define HV_SPHERE_DIFFUSE_HORIZON 1

// sphere_specular (HV_SPHERE_SPECULAR): representative_point, ltc
#define HV_SPHERE_SPECULAR_REPRESENTATIVE_POINT 0
#define HV_SPHERE_SPECULAR_LTC 1

// tube_specular (HV_TUBE_SPECULAR): closest_point_eq19, smallest_angle_eq18, ltc
#define HV_TUBE_SPECULAR_CLOSEST_POINT 0
#define HV_TUBE_SPECULAR_SMALLEST_ANGLE 1
#define HV_TUBE_SPECULAR_LTC 2

// tube_diffuse (HV_TUBE_DIFFUSE): karis_eq16, ltc
#define HV_TUBE_DIFFUSE_KARIS_EQ16 0
#define HV_TUBE_DIFFUSE_LTC 1

// ibl_direction (HV_IBL_DIRECTION): dominant, reflect
#define HV_IBL_DIRECTION_DOMINANT 0
#define HV_IBL_DIRECTION_REFLECT 1

// ibl_specular (HV_IBL_SPECULAR): split_sum, sampled
#define HV_IBL_SPECULAR_SPLIT_SUM 0
#define HV_IBL_SPECULAR_SAMPLED 1

// ao (HV_AO): none, gtao
#define HV_AO_NONE 0
#define HV_AO_GTAO 1

// ao_quality (HV_AO_QUALITY): low, medium, high
#define HV_AO_QUALITY_LOW 0
#define HV_AO_QUALITY_MEDIUM 1
#define HV_AO_QUALITY_HIGH 2

// ao_resolution (HV_AO_HALF_RESOLUTION): full, half
#define HV_AO_RESOLUTION_FULL 0
#define HV_AO_RESOLUTION_HALF 1

// ao_specular (HV_AO_SPECULAR): none, lagarde, cone, traced
#define HV_AO_SPECULAR_NONE 0
#define HV_AO_SPECULAR_LAGARDE 1
#define HV_AO_SPECULAR_CONE 2
#define HV_AO_SPECULAR_TRACED 3

// shadow_filter (HV_SHADOW_FILTER): hard, pcf, pcss
#define HV_SHADOW_FILTER_HARD 0
#define HV_SHADOW_FILTER_PCF 1
#define HV_SHADOW_FILTER_PCSS 2

// shadow_resolution (HV_SHADOW_RESOLUTION): full, half
#define HV_SHADOW_RESOLUTION_FULL 0
#define HV_SHADOW_RESOLUTION_HALF 1

// shadow_quality (HV_SHADOW_QUALITY): medium, high
#define HV_SHADOW_QUALITY_MEDIUM 0
#define HV_SHADOW_QUALITY_HIGH 1

#endif  // HV_SETTING_VALUES_GLSL

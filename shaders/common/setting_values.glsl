// The values of every enumerated render setting that reaches a shader as a define, written once
// for both languages: the shaders compare HV_BRDF_D and the other defines against these names,
// and the C++ enums of halfvec/scene/render_settings.hpp take their values from them, so a
// scene setting and the code it selects cannot drift apart. The settings themselves (key,
// default, define, feature) are the rows of HV_RENDER_SETTINGS in that header. Two-valued
// settings whose define is a flag (culling, env_brdf, irradiance) need no names here: their
// define is 1 for the second value.
#ifndef HV_SETTING_VALUES_GLSL
#define HV_SETTING_VALUES_GLSL

// brdf.d (HV_BRDF_D): the microfacet distribution (Karis 2013, "Specular D").
#define HV_D_GGX 0
#define HV_D_BECKMANN 1
#define HV_D_BLINN_PHONG 2

// brdf.v (HV_BRDF_V): the visibility term G / (4 NoL NoV) (Karis 2013, "Specular G").
#define HV_V_SCHLICK_GGX 0
#define HV_V_SMITH_GGX_CORRELATED 1
#define HV_V_SMITH_GGX_CORRELATED_FAST 2
#define HV_V_SMITH_GGX_SEPARABLE 3
#define HV_V_SMITH_BECKMANN_SEPARABLE 4
#define HV_V_COOK_TORRANCE 5
#define HV_V_IMPLICIT 6

// brdf.f (HV_BRDF_F): Fresnel (Karis 2013, "Specular F").
#define HV_F_SCHLICK 0
#define HV_F_SCHLICK_SG 1
#define HV_F_EXACT 2
#define HV_F_SCHLICK_F90_OCCLUSION 3

// brdf.diffuse (HV_BRDF_FD).
#define HV_FD_LAMBERT 0
#define HV_FD_BURLEY 1

// sphere_diffuse (HV_SPHERE_DIFFUSE): Karis's point approximation or the horizon-correct sphere
// irradiance (Lagarde & de Rousiers 2014, section 4.7).
#define HV_SPHERE_DIFFUSE_KARIS_POINT 0
#define HV_SPHERE_DIFFUSE_HORIZON 1

// sphere_specular (HV_SPHERE_SPECULAR): representative point (Karis eqs. 10, 11, 14) or LTC.
#define HV_SPHERE_SPECULAR_REPRESENTATIVE_POINT 0
#define HV_SPHERE_SPECULAR_LTC 1

// tube_specular (HV_TUBE_SPECULAR): closest point to the reflection ray (Karis eq. 19),
// smallest angle (eq. 18), LTC over the capsule.
#define HV_TUBE_SPECULAR_CLOSEST_POINT 0
#define HV_TUBE_SPECULAR_SMALLEST_ANGLE 1
#define HV_TUBE_SPECULAR_LTC 2

// tube_diffuse (HV_TUBE_DIFFUSE): Karis eq. 16 or the capsule's irradiance (identity LTC).
#define HV_TUBE_DIFFUSE_KARIS_EQ16 0
#define HV_TUBE_DIFFUSE_LTC 1

// tone_map (HV_TONEMAP): Reinhard per channel (Reinhard et al. 2002, eq. 3), on luminance, none
// (clamp), Khronos PBR Neutral, ACES (Narkowicz's fit).
#define HV_TONEMAP_REINHARD 0
#define HV_TONEMAP_REINHARD_LUMINANCE 1
#define HV_TONEMAP_NONE 2
#define HV_TONEMAP_PBR_NEUTRAL 3
#define HV_TONEMAP_ACES 4

// shadow_filter (HV_SHADOW_FILTER): one tap, a fixed-radius PCF, or PCSS (Fernando 2005).
#define HV_SHADOW_FILTER_HARD 0
#define HV_SHADOW_FILTER_PCF 1
#define HV_SHADOW_FILTER_PCSS 2

// ibl_direction (HV_IBL_DIRECTION): the direction the prefiltered radiance is read along, the
// dominant direction of the specular lobe (Lagarde & de Rousiers 2014, section 4.9.3) or the
// mirror direction R (Karis 2013).
#define HV_IBL_DIRECTION_DOMINANT 0
#define HV_IBL_DIRECTION_REFLECT 1

// gamma (HV_GAMMA): gamma 2.2 or exact sRGB (IEC 61966-2-1).
#define HV_GAMMA_22 0
#define HV_GAMMA_SRGB 1

// ao (HV_AO): screen-space ambient occlusion, none or ground-truth-based (Jimenez et al. 2016;
// docs/ambient-occlusion.md).
#define HV_AO_NONE 0
#define HV_AO_GTAO 1
// ao_quality (HV_AO_QUALITY): directions x steps per side of the horizon search (ao.glsl).
#define HV_AO_QUALITY_LOW 0
#define HV_AO_QUALITY_MEDIUM 1
#define HV_AO_QUALITY_HIGH 2
// ao_resolution (HV_AO_HALF_RESOLUTION): the AO buffer at the frame's size or half of it.
#define HV_AO_RESOLUTION_FULL 0
#define HV_AO_RESOLUTION_HALF 1
// ao_specular (HV_AO_SPECULAR): specular occlusion with `ao: gtao`: none, Lagarde & de Rousiers
// 2014 (from the visibility and roughness) or the cone-cone form (Jimenez et al. 2016, section 6:
// bent normal).
#define HV_AO_SPECULAR_NONE 0
#define HV_AO_SPECULAR_LAGARDE 1
#define HV_AO_SPECULAR_CONE 2
#endif  // HV_SETTING_VALUES_GLSL

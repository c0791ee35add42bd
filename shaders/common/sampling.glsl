// Sample generation and pdfs for image-based lighting and the CPU reference, shared by GLSL and C++
// (see halfvec/shading/glsl.hpp). Tangent space: z = normal.
#ifndef HV_SAMPLING_GLSL
#define HV_SAMPLING_GLSL

#include "math.glsl"
#include "brdf.glsl"

// Van der Corput radical inverse in base 2 (Hammersley points; Karis 2013 course notes, and
// Holger Dammertz, "Hammersley Points on the Hemisphere"): reverse the 32 bits of i and scale by
// 2^-32. Written with shifts and masks rather than bitfieldReverse() so C++ runs the same code.
float radicalInverseVdC(uint bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  // Keep the top 24 bits, which a float holds exactly, and scale by 2^-24. The usual
  // float(bits) * 2^-32 rounds bits >= 0xFFFFFF80 up to 2^32 and returns 1.0, outside [0,1).
  return float(bits >> 8u) * 5.9604644775390625e-8f;
}

// Hammersley point i of n in [0,1)^2 (Karis 2013, "Image Based Lighting", Hammersley()).
vec2 hammersley(uint i, uint n) { return vec2(float(i) / float(n), radicalInverseVdC(i)); }

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited" (JCGT 6(1)), listing 3: a
// branchless orthonormal basis T, B around unit N (right-handed: cross(T, B) = N).
void tangentFrame(vec3 N, HV_OUT(vec3) T, HV_OUT(vec3) B) {
  // copysign(1, N.z) without a branch; step(0, 0) = 1, so N.z = 0 takes the + side as in Duff.
  float s = 2.0f * step(0.0f, N.z) - 1.0f;
  float a = -1.0f / (s + N.z);
  float b = N.x * N.y * a;
  T = vec3(1.0f + s * N.x * N.x * a, s * b, -s * N.x);
  B = vec3(b, s + N.y * N.y * a, -N.y);
}

// Karis 2013, "Image Based Lighting", ImportanceSampleGGX: a half vector H distributed with pdf
// D_GGX(H) NoH (solid angle, w.r.t. H); returned in world space around the unit normal N.
// cos(theta) = sqrt((1 - u) / (1 + (a^2 - 1) u)) inverts the GGX CDF (Walter et al. 2007 eq. 35).
vec3 importanceSampleGGX(vec2 xi, float alpha, vec3 N) {
  float a2 = alpha * alpha;
  float phi = 2.0f * PI * xi.x;
  float cos_theta = sqrt((1.0f - xi.y) / (1.0f + (a2 - 1.0f) * xi.y));
  // max(0): cos_theta may round above 1 by an ulp.
  float sin_theta = sqrt(max(0.0f, 1.0f - cos_theta * cos_theta));
  vec3 T;
  vec3 B;
  tangentFrame(N, T, B);
  return T * (sin_theta * cos(phi)) + B * (sin_theta * sin(phi)) + N * cos_theta;
}

// pdf (solid angle, w.r.t. H) of importanceSampleGGX: D(h) (n.h) (Walter et al. 2007 eq. 24).
// The pdf of the reflected L = reflect(-V, H) is this divided by 4 VoH (Walter et al. eq. 14).
float pdfGGX(float alpha, float NoH) { return D_GGX(alpha, NoH) * NoH; }

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)): a microfacet normal
// distributed with the visible-normal density D_V(H) = G1(V) max(0, VoH) D(H) / V.z (eq. 3), for
// V_tangent in tangent space (z = normal, V.z > 0), isotropic alpha; returns the tangent-space H.
// The sampler is the branch-free spherical-cap form of Dupuy & Benyoub 2023, "Sampling Visible
// GGX Normals with Spherical Caps" (listing 3), which draws the same distribution as Heitz's
// listing without its "lensq > 0" branch.
vec3 sampleGGXVNDF(vec3 V_tangent, float alpha, vec2 u) {
  // Warp to the hemisphere configuration (alpha = 1).
  vec3 Vh = normalize(vec3(alpha * V_tangent.x, alpha * V_tangent.y, V_tangent.z));
  // Sample the spherical cap z in (-Vh.z, 1], phi uniform (Dupuy & Benyoub 2023 section 3).
  float phi = 2.0f * PI * u.x;
  float z = (1.0f - u.y) * (1.0f + Vh.z) - Vh.z;
  float sin_theta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
  vec3 c = vec3(sin_theta * cos(phi), sin_theta * sin(phi), z);
  // The halfway vector of Vh and c is the alpha = 1 normal (h.z >= 0 by construction); warp
  // back. safeNormalize: c = -Vh only on a set of measure zero (u.y = 1).
  vec3 h = c + Vh;
  return safeNormalize(vec3(alpha * h.x, alpha * h.y, h.z));
}

// pdf (solid angle, w.r.t. H) of sampleGGXVNDF: Heitz 2018 eq. 3,
// D_V(H) = G1(V) max(0, V.H) D(H) / V.z, with G1 of Walter et al. 2007 eq. 34 (Smith GGX).
// G1(V)/V.z = 2 / (V.z + sqrt(V.z^2 (1 - a^2) + a^2)) avoids dividing by V.z. The pdf of the
// reflected L is this divided by 4 VoH, i.e. G1(V) D(H) / (4 V.z).
float pdfGGXVNDF(vec3 V_tangent, vec3 H_tangent, float alpha) {
  float a2 = alpha * alpha;
  float NoV = V_tangent.z;
  float G1_over_NoV = 2.0f / (NoV + sqrt(NoV * NoV * (1.0f - a2) + a2));
  // 1 - H.z^2 = H.x^2 + H.y^2: no cancellation at the lobe's peak (see D_GGX).
  float sin2_NH = H_tangent.x * H_tangent.x + H_tangent.y * H_tangent.y;
  return G1_over_NoV * max(0.0f, dot(V_tangent, H_tangent)) * D_GGX(alpha, H_tangent.z, sin2_NH);
}

// Cosine-weighted hemisphere sample in tangent space (Malley's method: a uniform disk point
// r = sqrt(u.x) lifted to the hemisphere); pdf = cos(theta) / pi (see pdfCosineHemisphere).
vec3 sampleCosineHemisphere(vec2 u) {
  float r = sqrt(u.x);
  float phi = 2.0f * PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), sqrt(1.0f - u.x));  // u.x in [0,1): no clamp needed
}

// pdf (solid angle) of sampleCosineHemisphere: cos(theta) / pi.
float pdfCosineHemisphere(float cos_theta) { return max(cos_theta, 0.0f) * INV_PI; }

#endif

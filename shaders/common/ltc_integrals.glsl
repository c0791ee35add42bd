// Integrals of the clamped cosine D_o(w) = max(0, w.z) / pi over spherical regions: the closed
// forms that linearly transformed cosines reduce every emitter to (Heitz, Dupuy, Hill, Neubelt
// 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines", section 3), shared
// by GLSL and C++ (see halfvec/shading/glsl.hpp). Derivations and measured accuracy: docs/lights.md
// ("LTC sphere and tube lights").
//
// Each region is reduced to its vector form factor F = (1/pi) integral of w over the region
// (unclipped). F.z is the exact integral of D_o when the region lies above the horizon z = 0; when
// it straddles the horizon, the clipped integral is approximated by that of the sphere cap with
// the same F (Hill & Heitz 2016, "Real-Time Area Lighting: a Journey from Research to
// Production", the "clipless" horizon: |F| = sin^2 of the cap's half-angle, F/|F| its axis),
// whose clipped integral is Snyder's closed form (sphereHorizonFactor). F is additive over
// disjoint regions, so a capsule is the sum of its parts, clipped once.
#ifndef HV_LTC_INTEGRALS_GLSL
#define HV_LTC_INTEGRALS_GLSL

#include "math.glsl"
// tangentFrame (thinConeFormFactor)
#include "sampling.glsl"

// Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", section 4.7.2 listing 7
// (illuminanceSphereOrDisk, after Snyder 1996): integral of cos over the visible part of a sphere
// of sin^2(half-angle) = sin_sigma2 whose center is at angle theta from the normal, horizon
// clipped. Returned divided by pi sin_sigma2, so it equals saturate(cos_theta) when the sphere is
// entirely above or below the horizon; the caller multiplies by I / d^2.
float sphereHorizonFactor(float cos_theta, float sin_sigma2) {
  // sin_sigma2 in [1e-8, 1]: 1 means the point is inside the sphere; 1e-8 (radius 1e-4 d) keeps
  // 1/sin_sigma2 finite for radius 0, where the result is the point light's saturate(cos_theta).
  float s2 = clamp(sin_sigma2, 1e-8f, 1.0f);
  float above = saturate(cos_theta);
  // cos^2 >= sin^2(sigma): the sphere does not cross the horizon. The common case, and one that
  // neighbouring pixels share: a branch, which measured faster than computing both and selecting
  // even on llvmpipe, where both sides run under a mask (docs/lights.md).
  if (cos_theta * cos_theta >= s2) return above;
  // Straddling the horizon. sin_theta >= 1e-4 and x >= 1e-4 only guard 0/0 inside the sphere
  // (s2 = 1), where the value is bounded anyway.
  float sin_theta = sqrt(max(1.0f - cos_theta * cos_theta, 1e-8f));
  float x = sqrt(max(1.0f / s2 - 1.0f, 1e-8f));
  float y = clamp(-x * cos_theta / sin_theta, -1.0f, 1.0f);
  float sin_theta_sqrt_y = sin_theta * sqrt(1.0f - y * y);
  float straddle = ((cos_theta * acos(y) - x * sin_theta_sqrt_y) * s2 +
                    atan(sin_theta_sqrt_y / x)) / (PI * s2);
  return max(straddle, 0.0f);
}

// Integral of D_o over a region of vector form factor F, clipped at the horizon: exact for a
// region entirely above it (F.z), the sphere-cap approximation otherwise (see the top of file).
// |F| <= 1 for any region seen from one side; 1e-30 guards the empty region (F = 0 -> 0).
float horizonClippedIntegral(vec3 F) {
  float f2 = dot(F, F);
  float inv_f = inversesqrt(max(f2, 1e-30f));
  float f = min(f2 * inv_f, 1.0f);
  return f * sphereHorizonFactor(F.z * inv_f, f);
}

// theta / sin(theta) for cos(theta) = x in (-1, 1]: the weight of one polygon edge (Lambert's
// edge formula). Near x = 1, acos loses precision and both tend to 0: the series
// 1 + y/3 + 2y^2/15 + 2y^3/35 in y = 1 - x (truncation < 2e-6 for y < 0.05) is used there.
float edgeWeight(float x) {
  float y = 1.0f - x;
  float series = 1.0f + y * (1.0f / 3.0f + y * (2.0f / 15.0f + y * (2.0f / 35.0f)));
  // 1 - x^2 >= 1e-7: adjacent vertices are never antipodal (x = -1); only guards 0/0.
  float direct = acos(clamp(x, -1.0f, 1.0f)) * inversesqrt(max(1.0f - x * x, 1e-7f));
  return mix(direct, series, step(y, 0.05f));
}

// Lambert's formula (Heitz et al. 2016 eq. 11, Arvo 1995): vector form factor of the spherical
// polygon with vertex directions p0..p3 (any lengths, in order; the result points to the side the
// polygon is seen from when the vertices turn counter-clockwise around it):
// F = (1 / 2 pi) sum_i theta_i (v_i x v_i+1) / |v_i x v_i+1|.
vec3 quadFormFactor(vec3 p0, vec3 p1, vec3 p2, vec3 p3) {
  // safeNormalize: a degenerate quad (zero width or length, seen end-on) has zero vertices; its
  // edges then add 0.
  vec3 v0 = safeNormalize(p0);
  vec3 v1 = safeNormalize(p1);
  vec3 v2 = safeNormalize(p2);
  vec3 v3 = safeNormalize(p3);
  vec3 F = cross(v0, v1) * edgeWeight(dot(v0, v1)) + cross(v1, v2) * edgeWeight(dot(v1, v2)) +
           cross(v2, v3) * edgeWeight(dot(v2, v3)) + cross(v3, v0) * edgeWeight(dot(v3, v0));
  return F * (0.5f * INV_PI);
}

// Vector form factor of the elliptical cone {x : x^T Q x >= 0, x.toward > 0} (one nappe), for a
// symmetric Q with one positive eigenvalue mu (the cone's axis e) and two negative ones -l1, -l2:
// in the frame of its eigenvectors the cone is l1 y^2 + l2 z^2 <= mu x^2, tangent half-angles
// t_i = sqrt(mu / l_i), and F = e t1 t2 / sqrt((1 + t1^2)(1 + t2^2))
//                             = e mu / sqrt((mu + l1)(mu + l2))
// (integral of cos over an ellipse of semi-axes t1, t2 at unit distance, facing the origin:
// pi t1 t2 / sqrt((1 + t1^2)(1 + t2^2)); docs/lights.md derives it). Q = (q00, q01, q02, q11,
// q12, q22); det_q = det(Q) = mu l1 l2 > 0, given by the caller in closed form because it keeps
// its relative precision when the cone is thin (mu << l1, l2), where the eigenvalue formula
// below does not: mu is then taken as det_q / (l1 l2).
vec3 coneFormFactor(float q00, float q01, float q02, float q11, float q12, float q22, float det_q,
                    vec3 toward) {
  // Eigenvalues of a symmetric 3x3 (Smith 1961): q + 2 p cos(phi + 2 pi k / 3).
  float q = (q00 + q11 + q22) * (1.0f / 3.0f);
  float b00 = q00 - q;
  float b11 = q11 - q;
  float b22 = q22 - q;
  float off2 = q01 * q01 + q02 * q02 + q12 * q12;
  float p = sqrt(max((b00 * b00 + b11 * b11 + b22 * b22 + 2.0f * off2) * (1.0f / 6.0f), 1e-37f));
  float det_b = b00 * (b11 * b22 - q12 * q12) - q01 * (q01 * b22 - q12 * q02) +
                q02 * (q01 * q12 - b11 * q02);
  float phi = acos(clamp(det_b / (2.0f * p * p * p), -1.0f, 1.0f)) * (1.0f / 3.0f);
  float e_max = q + 2.0f * p * cos(phi);
  float e_min = q + 2.0f * p * cos(phi + 2.0943951023931953f);  // + 2 pi / 3
  float e_mid = 3.0f * q - e_max - e_min;
  // mu: the largest eigenvalue, or det / (l1 l2) when it is small next to l1 (thin cone: the
  // formula above has an absolute error of about 1e-7 p there). max(., tiny) keeps a degenerate
  // (empty) cone at F = 0.
  float l1 = max(-e_mid, 1e-37f);
  float l2 = max(-e_min, 1e-37f);
  float mu_det = det_q / (l1 * l2);
  // A select (bool mix), not a blend: the branch not taken may be inf for a degenerate cone.
  // No eigenvalue exceeds |q| + 2p in magnitude: the bound keeps a cone too ill-conditioned for float (l1 lost
  // to rounding) finite instead of inf.
  float mu = clamp(mix(e_max, mu_det, e_max < 0.25f * l1), 0.0f, abs(q) + 2.0f * p);
  float f = mu * inversesqrt(max((mu + l1) * (mu + l2), 1e-37f));
  // Axis: the null vector of Q - mu I, the largest cross product of two of its rows.
  vec3 ra = vec3(q00 - mu, q01, q02);
  vec3 rb = vec3(q01, q11 - mu, q12);
  vec3 rc = vec3(q02, q12, q22 - mu);
  vec3 x1 = cross(ra, rb);
  vec3 x2 = cross(rb, rc);
  vec3 x3 = cross(rc, ra);
  float d1 = dot(x1, x1);
  float d2 = dot(x2, x2);
  float d3 = dot(x3, x3);
  vec3 e = mix(x1, x2, step(d1, d2));
  e = mix(e, x3, step(max(d1, d2), d3));
  e = e * inversesqrt(max(dot(e, e), 1e-37f));
  // The nappe on the side of `toward`.
  e = e * (2.0f * step(0.0f, dot(e, toward)) - 1.0f);
  return e * min(f, 1.0f);
}

// The same cone's form factor where its image is thin or elongated: its positive eigenvalue mu
// and the smaller negative one -l1 both small next to -l2 (mu, l1 < l2 / 4), as an LTC makes a
// light's cone in its far tail at grazing views and low roughness. There Q's entries are of order
// l2, mu and l1 are below their float rounding (1e-7 l2) and coneFormFactor's eigenvalues lose
// them, which gave `ltc` spheres seen at N.V 0.03-0.06 on a roughness-0.1 floor values up to 255x
// the reference (docs/lights.md, "Thin cones"). Here mu comes from a matrix where it is large. The
// cone is {B (a, b, h): a^2 + b^2 <= h^2} with B = [t a1, t a2, c] (the images of the disk's
// basis; t = tan(sigma)), Q = G^T J G with G = det(B) B^-1 / t (the rows r1, r2, r3 of
// ltcSphereFormFactor), J = diag(-1, -1, 1), so adj(Q) = det^2 A with A = c c^T - t^2 (a1 a1^T +
// a2 a2^T), three rank-one terms (det = det[a1 a2 c]), whose eigenvalues are det(Q) / (det^2
// lambda) for Q's lambda: those of mu and -l1 the two large ones. The eigenvector u of -l2, Q's
// dominant one, is found well from Q itself (its largest row, one power step); A restricted to the
// plane across u is a 2x2 problem whose larger eigenvalue beta gives mu = t^2 det^2 / beta and
// the axis. With l1 + l2 = mu - trace(Q) and l1 l2 = det(Q) / mu (`trace` = trace(Q), dominated
// by -l2; det(Q) = det^4 t^2 in closed form), the form factor mu / sqrt((mu + l1)(mu + l2)) needs
// neither l1 nor l2 alone. Returns (F, 1) where mu and l1 are below l2 / 4 by these values, (0, 0)
// otherwise (coneFormFactor then). Scale-free in c, a1, a2 (as Q is).
vec4 thinConeFormFactor(vec3 c, vec3 a1, vec3 a2, float t, float det, float q00, float q01,
                        float q02, float q11, float q12, float q22) {
  // u: Q's largest row, then one step of power iteration.
  vec3 ra = vec3(q00, q01, q02);
  vec3 rb = vec3(q01, q11, q12);
  vec3 rc = vec3(q02, q12, q22);
  vec3 u = dot(ra, ra) > dot(rb, rb) ? ra : rb;
  u = dot(rc, rc) > dot(u, u) ? rc : u;
  u = vec3(dot(ra, u), dot(rb, u), dot(rc, u));
  u = u * inversesqrt(max(dot(u, u), 1e-37f));
  // An orthonormal basis p, q of the plane across u, and A there.
  vec3 p;
  vec3 q;
  tangentFrame(u, p, q);
  float t2 = t * t;
  vec3 pc = vec3(dot(p, c), dot(p, a1), dot(p, a2));
  vec3 qc = vec3(dot(q, c), dot(q, a1), dot(q, a2));
  float app = pc.x * pc.x - t2 * (pc.y * pc.y + pc.z * pc.z);
  float apq = pc.x * qc.x - t2 * (pc.y * qc.y + pc.z * qc.z);
  float aqq = qc.x * qc.x - t2 * (qc.y * qc.y + qc.z * qc.z);
  float mid = 0.5f * (app + aqq);
  float beta = mid + sqrt(sq(0.5f * (app - aqq)) + apq * apq);
  // Its eigenvector: the larger of the two forms of the null vector of A - beta.
  vec2 v1 = vec2(apq, beta - app);
  vec2 v2 = vec2(beta - aqq, apq);
  vec2 v = dot(v1, v1) > dot(v2, v2) ? v1 : v2;
  vec3 e = p * v.x + q * v.y;
  e = e * inversesqrt(max(dot(e, e), 1e-37f));
  float d2 = det * det;
  float mu = t2 * d2 / max(beta, 1e-37f);
  float trace = q00 + q11 + q22;
  float sum_l = mu - trace;                       // l1 + l2
  float prod_l = d2 * t2 * d2 / max(mu, 1e-37f);  // l1 l2 = det(Q) / mu
  // l2, the larger root of x^2 - sum_l x + prod_l, and l1 = prod_l / l2 (no cancellation).
  float l2 = 0.5f * (sum_l + sqrt(max(sum_l * sum_l - 4.0f * prod_l, 0.0f)));
  float l1 = prod_l / max(l2, 1e-37f);
  float f = mu * inversesqrt(max(mu * mu + mu * sum_l + prod_l, 1e-37f));
  // The nappe on the side of c.
  e = e * (2.0f * step(0.0f, dot(e, c)) - 1.0f);
  bool thin = beta > 0.0f && max(mu, l1) < 0.25f * l2;
  return thin ? vec4(e * min(f, 1.0f), 1.0f) : vec4(0.0f);
}

#endif

// Linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016, "Real-Time Polygonal-Light
// Shading with Linearly Transformed Cosines"; Heitz & Hill 2017, "Real-Time Line- and Disk-Light
// Shading with Linearly Transformed Cosines") fitted to the engine's own specular lobe, shared by
// GLSL and C++ (see halfvec/shading/glsl.hpp). The table is fitted by `halfvec ltc-fit`
// (engine/eval/src/ltc_fit.cpp) from the terms of brdf.glsl; the method, the table and the
// measured accuracy: docs/lights.md ("LTC sphere and tube lights").
//
// An LTC is the distribution D(w) of w = M w_o / |M w_o| for w_o drawn from the clamped cosine
// D_o(w_o) = max(0, w_o.z) / pi (Heitz et al. eq. 1):  D(w) = D_o(w_o) / |det M| |M w_o|^3 with
// w_o = M^-1 w / |M^-1 w|, so that the integral of D over any region P of directions is the
// integral of D_o over M^-1 P (eq. 5), in closed form for polygons, disks (elliptical cones) and
// lines (ltc_integrals.glsl). Per cell of (roughness, N.V), M is fitted so that D approximates
// the normalized lobe f(v, l) (n.l) / n_f, n_f = its integral (the directional albedo with F = 1).
//
// Parametrization of M (isotropic lobes are symmetric about the plane of incidence): in the
// shading frame (T1 in the plane of incidence, T2 = N x T1, N), with the lobe's mean direction
// Z' = (d_x, 0, d_z) and X' = (d_z, 0, -d_x):
//   M = [X' T2 Z'] * [[a_x, 0, 0], [0, a_y, 0], [s, 0, 1]],
// so M maps the cosine's axis onto Z' exactly and its x and y axes onto lobe widths a_x, a_y,
// with s the skew of the lobe toward (or away from) the mean direction. For small alpha both
// widths scale as alpha, so the table stores a_x / alpha, a_y / alpha (nearly constant as
// alpha -> 0: what bilinear filtering interpolates well), the skew s itself (it shears the
// axis's component, and stays O(0.01-1) at every roughness) and the axis as its tilt
// tau from the mirror direction: Z''s polar angle (toward the mirror side, d_x = -sin) is
// acos(N.V) + tau. d_x itself varies fastest where N.V -> 0 and its bilinear interpolation
// between rows there moved a glossy lobe's axis by about its width (at roughness 0.05, N.V
// 0.048: the table's LTC integrated a light at the lobe's edge to 1.63 times what the LTC fitted
// at that N.V does); tau is small and smooth (-2e-4 to -4e-5 rad at roughness 0.045 on the
// grazing rows). The second texture stores the magnitudes n_f and the Fresnel weight integral of
// (1 - V.H)^5.
#ifndef HV_LTC_GLSL
#define HV_LTC_GLSL

#include "math.glsl"
#include "brdf.glsl"
#include "ltc_integrals.glsl"
#include "sampling.glsl"

// Table: HV_LTC_TABLE_SIZE^2 cells; x = (roughness - HV_MIN_ROUGHNESS) / (1 - HV_MIN_ROUGHNESS),
// y = sqrt((1 - N.V) / (1 - HV_LTC_MIN_NOV)) (more cells toward grazing views, where the lobe
// changes fastest; the last row is the smallest N.V looked up, not a lobe no pixel reads, whose
// bilinear blend into the rows above it the table had before); cell (i,j) is fitted at
// x = i / (size - 1), y = j / (size - 1). Two RGBA textures (texture units below), sampled with
// linear filtering and clamp-to-edge: tex 0 = (a_x / alpha, a_y / alpha, s, tau), tex 1 = (n_f,
// n_fresnel, 0, 0) with n_fresnel = integral of f (n.l) (1 - V.H)^5.
#define HV_LTC_TABLE_SIZE 64
#define HV_LTC_TEXTURE_UNIT0 6
#define HV_LTC_TEXTURE_UNIT1 7

// Smallest N.V the LTC modes look up. Toward N.V = 0 the lobe's width across the plane of
// incidence goes to 0 (a_y ~ 2 alpha N.V), and below N.V = 0.02 at the lowest roughness the
// cosine space is stretched by 1e4 or more across, beyond what the cone integral's float
// eigenvalues resolve (found by the stability sweep: NaN at N.V = 1e-4, roughness 0.045). Silhouette
// pixels below it are shaded with the lobe of N.V = 0.02.
const float HV_LTC_MIN_NOV = 0.02f;

// Cell coordinates (texel units, 0 .. size - 1) of a roughness and N.V.
vec2 ltcCellCoord(float roughness, float NoV) {
  float x = saturate((roughness - HV_MIN_ROUGHNESS) / (1.0f - HV_MIN_ROUGHNESS));
  float y = saturate(sqrt(saturate(1.0f - NoV)) * inversesqrt(1.0f - HV_LTC_MIN_NOV));
  return vec2(x, y) * float(HV_LTC_TABLE_SIZE - 1);
}

// Texture coordinates of the same point: texel centers at (i + 0.5) / size.
vec2 ltcTableUv(float roughness, float NoV) {
  return (ltcCellCoord(roughness, max(NoV, HV_LTC_MIN_NOV)) + vec2(0.5f)) *
         (1.0f / float(HV_LTC_TABLE_SIZE));
}
// The (roughness, N.V) at table coordinates x, y in [0, 1] (inverse of ltcCellCoord / (size - 1)).
vec2 ltcTableParameters(float x, float y) {
  return vec2(HV_MIN_ROUGHNESS + (1.0f - HV_MIN_ROUGHNESS) * x,
              max(1.0f - y * y * (1.0f - HV_LTC_MIN_NOV), HV_LTC_MIN_NOV));
}
// The (roughness, N.V) a cell is fitted at.
vec2 ltcCellParameters(int i, int j) {
  return ltcTableParameters(float(i) / float(HV_LTC_TABLE_SIZE - 1),
                            float(j) / float(HV_LTC_TABLE_SIZE - 1));
}

// One LTC in world space, as what the integrals need: the rows of alpha M^-1 (world -> cosine
// space; the factor alpha keeps every entry O(1) at low roughness, and any positive factor leaves
// directions, hence the integrals, unchanged) and its determinant. From the parametrization,
// M^-1 = A^-1 [X' T2 Z']^T with A^-1 = [[1/a_x, 0, 0], [0, 1/a_y, 0], [-s/a_x, 0, 1]]: rows
// X'/a_x, T2/a_y, Z' - (s/a_x) X'; times alpha with the table's a_x/alpha, a_y/alpha and s:
// X'/(a_x/alpha), T2/(a_y/alpha), alpha Z' - (s/(a_x/alpha)) X'.
struct Ltc {
  vec3 i0;
  vec3 i1;
  vec3 i2;
  float det_inv;  // det(alpha M^-1) = alpha / ((a_x/alpha) (a_y/alpha))
  float peak;     // D at the cosine's axis (its largest value): 1 / (pi a_x a_y)
};

// The table's tilt tau of a lobe axis (d_x, d_z) fitted at N.V = cos_v (see the top).
float ltcTiltFromAxis(float dx, float cos_v) {
  return asin(clamp(-dx, -1.0f, 1.0f)) - acos(clamp(cos_v, 0.0f, 1.0f));
}
// The axis (d_x, d_z) of the tilt tau at N.V = cos_v: the polar angle acos(cos_v) + tau, at most
// the horizon's (d_z >= 0).
vec2 ltcAxisFromTilt(float tau, float cos_v) {
  float sin_v = sqrt(max(1.0f - cos_v * cos_v, 0.0f));
  float st = sin(tau);
  float ct = cos(tau);
  vec2 a = vec2(-(sin_v * ct + cos_v * st), max(cos_v * ct - sin_v * st, 0.0f));
  return a * inversesqrt(max(dot(a, a), 1e-30f));
}

// The LTC of the widths and skew (a_x/alpha, a_y/alpha, s) and the axis (d_x, d_z) in the
// plane of incidence, for the unit normal N, unit view V and the surface's alpha. The frame's
// T1 is V's component along the surface; at normal incidence any tangent does (the lobe is then
// symmetric about N): a 1e-6 nudge toward tangentFrame's T picks one without a branch and
// changes nothing measurable otherwise.
Ltc makeLtcAxis(vec3 N, vec3 V, float alpha, vec3 shape, float dx, float dz) {
  vec3 T;
  vec3 B;
  tangentFrame(N, T, B);
  vec3 T1 = safeNormalize(V - N * dot(N, V) + 1e-6f * T);
  vec3 T2 = cross(N, T1);
  vec3 Xp = T1 * dz - N * dx;
  vec3 Zp = T1 * dx + N * dz;
  Ltc l;
  l.i0 = Xp / shape.x;
  l.i1 = T2 / shape.y;
  l.i2 = Zp * alpha - Xp * (shape.z / shape.x);
  l.det_inv = alpha / (shape.x * shape.y);
  l.peak = INV_PI / (alpha * alpha * shape.x * shape.y);
  return l;
}

// The LTC of a table cell's parameters (tex 0) for N, V and alpha; the axis's tilt is taken from
// the mirror direction at the N.V the table is read at (ltcTableUv: at least HV_LTC_MIN_NOV).
Ltc makeLtc(vec3 N, vec3 V, float alpha, vec4 params) {
  vec2 a = ltcAxisFromTilt(params.w, max(dot(N, V), HV_LTC_MIN_NOV));
  return makeLtcAxis(N, V, alpha, vec3(params.x, params.y, params.z), a.x, a.y);
}

// The identity LTC about N (D = the clamped cosine itself): Lambertian irradiance.
Ltc ltcIdentity(vec3 N) {
  Ltc l;
  tangentFrame(N, l.i0, l.i1);
  l.i2 = N;
  l.det_inv = 1.0f;
  l.peak = INV_PI;
  return l;
}

// alpha M^-1 w: w in cosine space, up to the positive factor alpha.
vec3 ltcToCosine(Ltc l, vec3 w) { return vec3(dot(l.i0, w), dot(l.i1, w), dot(l.i2, w)); }

// D(w) for unit w (Heitz et al. 2016 eq. 2): D_o(w_o) |det M^-1| / |M^-1 w|^3, which with
// x = alpha M^-1 w is D_o(x / |x|) det(alpha M^-1) / |x|^3.
float ltcDensity(Ltc l, vec3 w) {
  vec3 x = ltcToCosine(l, w);
  // |x|^2 >= 1e-18: for a unit w, |x| is at least alpha M^-1's smallest singular value (~alpha);
  // only w = 0 reaches the clamp, where x.z = 0 makes D = 0 (and inv_len^4 stays finite).
  float inv_len = inversesqrt(max(dot(x, x), 1e-18f));
  return max(x.z, 0.0f) * INV_PI * l.det_inv * inv_len * inv_len * inv_len * inv_len;
}

// Vector form factor, in cosine space, of the sphere (center c relative to the shading point,
// radius r) seen from outside it: the cone it subtends is that of the disk facing the shading
// point (Heitz & Hill 2017's sphere light: the disk of equal solid angle, here the same cone
// exactly), of tangent half-angle tan(sigma) = r / sqrt(d^2 - r^2), whose image under M^-1 is an
// elliptical cone. With the disk's basis B = [t e1, t e2, c/d] (e1, e2 unit, perpendicular to c,
// t = tan(sigma)) mapped to cosine space, B' = M^-1 B, a point x lies in the cone iff its
// coordinates (a, b, h) = B'^-1 x satisfy a^2 + b^2 <= h^2: with the rows of det(B') B'^-1,
// r1 = B'1 x B'2 ... (cross products), the cone is x^T Q x >= 0 with Q = r3 r3^T - r1 r1^T - r2 r2^T
// and det Q = det(B')^4. Divided through by t^2 so that Q stays O(1) for small spheres.
vec3 ltcSphereFormFactor(Ltc l, vec3 c, float r) {
  // Outside only; from inside (and at the center) a finite stand-in: the cone of radius
  // 0.999 d, nearly the half-space toward c, which callers replace (ltcSphereIntegral) or
  // which is their answer's limit at the surface (the capsule's caps).
  float d2 = max(dot(c, c), 1e-30f);
  r = min(r, 0.999f * sqrt(d2));
  float k = d2 - r * r;
  float inv_d = inversesqrt(d2);
  vec3 cn = c * inv_d;
  float t = r * inversesqrt(k);
  vec3 e1;
  vec3 e2;
  tangentFrame(cn, e1, e2);  // right-handed: e1 x e2 = cn
  // Columns of B' (cosine space), e's unscaled: r1 = e2' x c', r2 = c' x e1', r3 = t^2 e1' x e2'
  // (all divided by t).
  vec3 cc = ltcToCosine(l, cn);
  vec3 a1 = ltcToCosine(l, e1);
  vec3 a2 = ltcToCosine(l, e2);
  vec3 r1 = cross(a2, cc);
  vec3 r2 = cross(cc, a1);
  vec3 r3 = cross(a1, a2) * t;
  float q00 = r3.x * r3.x - r1.x * r1.x - r2.x * r2.x;
  float q01 = r3.x * r3.y - r1.x * r1.y - r2.x * r2.y;
  float q02 = r3.x * r3.z - r1.x * r1.z - r2.x * r2.z;
  float q11 = r3.y * r3.y - r1.y * r1.y - r2.y * r2.y;
  float q12 = r3.y * r3.z - r1.y * r1.z - r2.y * r2.z;
  float q22 = r3.z * r3.z - r1.z * r1.z - r2.z * r2.z;
  // det Q / t^6 = det(B')^4 / t^6 with det B' = det(alpha M^-1) t^2 det[e1 e2 cn] = det_inv t^2.
  float di2 = l.det_inv * l.det_inv;
  float det_q = di2 * di2 * t * t;
  // A thin or elongated image (the lobe's far tail at grazing views) by thinConeFormFactor, which
  // keeps its precision there; any other by the eigenvalues of Q.
  vec4 F_thin = thinConeFormFactor(cc, a1, a2, t, l.det_inv, q00, q01, q02, q11, q12, q22);
  vec3 F = F_thin.w > 0.5f ? vec3(F_thin)
                           : coneFormFactor(q00, q01, q02, q11, q12, q22, det_q, cc);
  // A cone small next to the LTC's lobe (u^2 = pi t^2 peak < 1: its solid angle below the lobe's,
  // the scale 1 / sqrt(pi peak) = alpha sqrt(a_x a_y)) has the form factor of its center
  // direction: solid angle in cosine space (omega det(alpha M^-1) / |x|^3, x = alpha M^-1 cn) /
  // pi along x, whose z is omega times the density at cn. There the eigenvalues above can lose
  // all precision when the cone's image is thin and elongated (the lobe's far tail at roughness
  // <= 0.1, lights of r/d <= 1e-3: |F| 1e5 times too large, a firefly of 1e4 x the point light's
  // value, found by `halfvec stability`); the cone is replaced by that estimate when it exceeds
  // it 4 times (a legitimate cone of that size deviates from it by a few %).
  float omega = 2.0f * PI * t * t / (1.0f + t * t + sqrt(1.0f + t * t));  // 2 pi (1 - cos sigma)
  float cc2 = max(dot(cc, cc), 1e-30f);
  vec3 F_small = cc * (omega * l.det_inv * INV_PI / (cc2 * cc2));
  bool garbage = PI * t * t * l.peak < 1.0f && dot(F, F) > 16.0f * dot(F_small, F_small);
  return mix(F, F_small, bvec3(garbage));
}

// Integral of the LTC over the sphere light, clipped at the horizon in cosine space (the sphere-cap
// approximation when the image straddles it); 1 inside the sphere, where the whole hemisphere
// emits and the integral of the normalized lobe is 1 by construction.
float ltcSphereIntegral(Ltc l, vec3 c, float r) {
  float outside = horizonClippedIntegral(ltcSphereFormFactor(l, c, r));
  return mix(outside, 1.0f, dot(c, c) <= r * r);  // a select (bool mix)
}

// ---- A sphere straddling the surface's horizon ----
//
// The lobe is 0 below the surface, but the LTC's clamped cosine is 0 only below its own horizon in
// cosine space (the image of the cosine's hemisphere, not the surface's): for a sphere that
// straddles the surface's horizon, the clip in cosine space keeps the part of the sphere below
// the surface wherever the LTC leaks there (a sliver of a rough lobe's light: many times the
// reference). The horizon is cut in world space, where it is a plane: on the tangent plane at
// unit distance along the sphere's direction, the silhouette is a disk of radius tan(sigma) and
// the surface's horizon a chord of it. The smaller of the two segments the chord makes is a
// polygon (HV_LTC_SEGMENT_ARC_POINTS points on its arc, the chord closing it) whose vector form
// factor comes from Lambert's formula in cosine space (Heitz et al. 2016 eq. 11), scaled by the
// segment's area over the polygon's (exact as the segment shrinks); the part above the surface
// is that polygon where it is the smaller segment, else the cone's exact F less it. Cutting off
// the larger segment's polygon instead (the part below from the whole disk) leaves the polygon's
// error on a sliver above: the polygon, not the circle, decides a sliver's area. The part above
// is then clipped at the cosine space's horizon: exactly, as a polygon, where it is the smaller
// segment; as any region (horizonClippedIntegral) where it is the cone less the segment below.
// Where a sphere starts to straddle (the segment below vanishes) the second is the whole cone's
// integral. Measured: docs/lights.md, "Straddling spheres".
#define HV_LTC_SEGMENT_ARC_POINTS 8

// A sphere (center c relative to the shading point, radius r) that straddles the horizon of N
// from outside: the cases ltcSphereIntegralAbove is for.
bool ltcSphereStraddles(vec3 N, vec3 c, float r) {
  float h = dot(N, c);
  return h * h < r * r && dot(c, c) > r * r;
}

// One polygon edge's part of 2 pi F (Lambert's formula), for the cosine-space images a, b.
vec3 ltcEdgeFormFactor(vec3 a, vec3 b) {
  vec3 u = safeNormalize(a);
  vec3 v = safeNormalize(b);
  return cross(u, v) * edgeWeight(dot(u, v));
}

// The area of the segment of a unit disk beyond a chord at half-angle phi (the chord's distance
// from the center cos(phi)) over that of the polygon of n points on its arc (n - 1 chords) and
// the chord: (phi - sin phi cos phi) / ((n - 1) sin(2 phi / (n - 1)) / 2 - sin(2 phi) / 2). Both
// vanish as phi^3; below phi = 0.05, where float cancels, their ratio's limit 1 / (1 - (n-1)^-2).
float ltcSegmentAreaRatio(float phi) {
  float m = float(HV_LTC_SEGMENT_ARC_POINTS - 1);
  float seg = phi - sin(phi) * cos(phi);
  float poly = 0.5f * (m * sin(2.0f * phi / m) - sin(2.0f * phi));
  return phi < 0.05f ? 1.0f / (1.0f - 1.0f / (m * m)) : seg / max(poly, 1e-30f);
}

// One edge a -> b (cosine-space images) of a convex polygon clipped at a plane, ha and hb the
// ends' heights over it (> 0: kept): the kept part's share of 2 pi F (ltcEdgeFormFactor); the
// points where the boundary leaves the kept side and comes back go to x_down and x_up, whose
// edge along the plane closes the clipped polygon (ltcClosingEdge). The crossing's parameter
// along the edge is the same for a linear image of it, so world-space heights serve for
// cosine-space points.
vec3 ltcClippedEdge(vec3 a, vec3 b, float ha, float hb, HV_INOUT(vec3) x_down,
                    HV_INOUT(vec3) x_up) {
  vec3 x = a + (b - a) * (ha / (ha - hb + (ha == hb ? 1e-30f : 0.0f)));
  x_down = (ha > 0.0f && hb <= 0.0f) ? x : x_down;
  x_up = (ha <= 0.0f && hb > 0.0f) ? x : x_up;
  vec3 a_kept = ha > 0.0f ? a : x;
  vec3 b_kept = hb > 0.0f ? b : x;
  return (ha > 0.0f || hb > 0.0f) ? ltcEdgeFormFactor(a_kept, b_kept) : vec3(0.0f);
}
vec3 ltcClosingEdge(vec3 x_down, vec3 x_up) {
  bool cut = dot(x_down, x_down) > 0.0f && dot(x_up, x_up) > 0.0f;
  return cut ? ltcEdgeFormFactor(x_down, x_up) : vec3(0.0f);
}

// The part above the surface of normal N of the sphere (c, r as above; straddling it, wholly
// above or wholly below: the segment is then the whole disk or nothing): its vector form factor
// in the cosine space of l, oriented as the whole cone's (F_cone: ltcSphereFormFactor(l, c, r),
// which the callers also need); and, where the part above is the smaller segment (the center at
// or below the surface), its clamped cosine's integral exactly: the polygon clipped at the
// cosine space's horizon (z = 0), in I_exact (-1 elsewhere).
vec3 ltcSphereAboveFormFactor(Ltc l, vec3 N, vec3 c, float r, vec3 F_cone,
                              HV_OUT(float) I_exact) {
  float d2 = max(dot(c, c), 1e-30f);
  vec3 cn = c * inversesqrt(d2);
  float t = r * inversesqrt(max(d2 - r * r, 1e-30f));  // tan(sigma): the disk's radius
  vec3 e1;
  vec3 e2;
  tangentFrame(cn, e1, e2);
  vec3 up = N - cn * dot(N, cn);  // toward the disk's highest point over the surface
  float up2 = dot(up, up);
  e1 = up2 > 1e-12f ? up * inversesqrt(up2) : e1;
  e2 = cross(cn, e1);  // e1, e2, cn right-handed: angles turn counter-clockwise about cn
  // The chord: N . (cn + y e1) = 0 at y0 = -N.cn / |up| along e1.
  float y0 = clamp(-dot(N, cn) * inversesqrt(max(up2, 1e-30f)), -t, t);
  bool above_smaller = y0 >= 0.0f;
  float phi = acos(min(abs(y0) / max(t, 1e-30f), 1.0f));  // the segment's half-angle
  vec3 axis = above_smaller ? e1 : -e1;                    // toward the smaller segment's arc
  vec3 side = above_smaller ? e2 : -e2;
  // The arc's points from angle -phi to phi about axis (counter-clockwise about cn), turned by
  // a rotation of step 2 phi / (n - 1); the chord closes the polygon.
  float step_angle = 2.0f * phi / float(HV_LTC_SEGMENT_ARC_POINTS - 1);
  vec2 rot = vec2(cos(phi), -sin(phi));
  vec2 turn = vec2(cos(step_angle), sin(step_angle));
  vec3 first = ltcToCosine(l, cn + (axis * rot.x + side * rot.y) * t);
  vec3 prev = first;
  vec3 F = vec3(0.0f);
  vec3 Fc = vec3(0.0f);  // the same polygon clipped at z = 0
  vec3 x_down = vec3(0.0f);
  vec3 x_up = vec3(0.0f);
  for (int k = 1; k <= HV_LTC_SEGMENT_ARC_POINTS; ++k) {
    vec3 p = first;
    if (k < HV_LTC_SEGMENT_ARC_POINTS) {
      rot = vec2(rot.x * turn.x - rot.y * turn.y, rot.x * turn.y + rot.y * turn.x);
      p = ltcToCosine(l, cn + (axis * rot.x + side * rot.y) * t);
    }
    F += ltcEdgeFormFactor(prev, p);
    Fc += ltcClippedEdge(prev, p, prev.z, p.z, x_down, x_up);
    prev = p;
  }
  Fc += ltcClosingEdge(x_down, x_up);
  float scale = (0.5f * INV_PI) * ltcSegmentAreaRatio(phi);
  I_exact = above_smaller ? max(Fc.z * scale, 0.0f) : -1.0f;
  return above_smaller ? F * scale : F_cone - F * scale;
}

// ltcSphereIntegral for a sphere that straddles the horizon of N (ltcSphereStraddles): the
// integral over its part above the surface (ltcSphereAboveFormFactor), exact where that part is
// the smaller segment, else clipped as any region (horizonClippedIntegral).
float ltcSphereIntegralAbove(Ltc l, vec3 N, vec3 c, float r, vec3 F_cone) {
  float I_exact;
  vec3 F = ltcSphereAboveFormFactor(l, N, c, r, F_cone, I_exact);
  return I_exact >= 0.0f ? I_exact : horizonClippedIntegral(F);
}

// ---- Capsule (tube light): the cylinder's silhouette plus the two end caps ----
//
// Seen from the shading point, the cylinder of radius r around the segment p1 p2 fills the wedge
// between the two planes through the shading point tangent to it; between the planes through the
// shading point perpendicular to the axis at p1 and p2 ("end lines") that wedge is exactly the
// rectangle through the axis, facing the shading point (its width direction w is p1 x (p2 - p1),
// the same along the whole axis), of half-width h = r D / sqrt(D^2 - r^2), D the distance from the
// shading point to the axis line. That rectangle's integral is exact (Lambert's polygon formula in
// cosine space); Heitz & Hill 2017's line light is its limit for h -> 0. Each end cap (a sphere)
// adds the half of its disk beyond the end line: the disk's integral times the fraction of it
// there, estimated from the density at the two half-disks' centroids (4/(3 pi) of the radius
// either side of the end line; exact when the density varies linearly across the disk). The
// capsule contains each end sphere, so the larger of the two disks alone is a lower bound that
// takes over when the capsule is seen end-on (the rectangle then vanishes and the near cap hides
// the rest). Vector form factors add; the sum is clipped at the horizon once.

// The half-width vector w (|w| = h) of the facing rectangle of the segment p1 -> p2 seen from the
// origin; 0 when seen end-on.
vec3 capsuleHalfWidth(vec3 p1, vec3 p2, float r) {
  vec3 a = p2 - p1;
  vec3 pa = cross(p1, a);
  float pa2 = dot(pa, pa);
  // D^2 = |p1 x a|^2 / |a|^2; D^2 - r^2 >= 1e-8 D^2 (inside the cylinder the wedge is the whole
  // half-space: h -> infinity, bounded here at 1e4 r).
  float D2 = pa2 / max(dot(a, a), 1e-30f);
  float h = r * sqrt(D2 / max(D2 - r * r, 1e-8f * D2 + 1e-30f));
  return pa * (h * inversesqrt(max(pa2, 1e-30f)));
}

// Fraction of a cap's disk that lies beyond the end line, from the density `dout`, `din` at the
// two half-disks' centroids; one half when both are 0.
float capFraction(float dout, float din) {
  return mix(0.5f, dout / max(dout + din, 1e-37f), step(1e-37f, dout + din));
}

// Offsets of the half-disk centroids from the cap center c (unit), toward the outside: the
// component of the axis direction `a` perpendicular to c, scaled to 4/(3 pi) of the disk's radius
// tan(sigma) (in the plane tangent at c).
vec3 capCentroidOffset(vec3 c, vec3 a, float t) {
  vec3 ap = a - c * dot(c, a);
  return ap * (0.42441318f * t * inversesqrt(max(dot(ap, ap), 1e-30f)));
}

// The capsule's vector form factor from its facing rectangle's (F) and its end spheres' (F1 at
// p1, F2 at p2): each cap adds the fraction of its sphere beyond the end line, and the capsule's
// integral is at least either sphere's.
vec3 ltcCapsuleWithCaps(Ltc l, vec3 F, vec3 F1, vec3 F2, vec3 p1, vec3 p2, float r) {
  vec3 a = p2 - p1;
  float d1 = dot(p1, p1);
  float d2 = dot(p2, p2);
  vec3 c1 = p1 * inversesqrt(max(d1, 1e-30f));
  vec3 c2 = p2 * inversesqrt(max(d2, 1e-30f));
  vec3 o1 = capCentroidOffset(c1, a, r * inversesqrt(max(d1 - r * r, 1e-30f)));
  vec3 o2 = capCentroidOffset(c2, -a, r * inversesqrt(max(d2 - r * r, 1e-30f)));
  float f1 = capFraction(ltcDensity(l, safeNormalize(c1 - o1)), ltcDensity(l, safeNormalize(c1 + o1)));
  float f2 = capFraction(ltcDensity(l, safeNormalize(c2 - o2)), ltcDensity(l, safeNormalize(c2 + o2)));
  F = F + F1 * f1 + F2 * f2;
  // The capsule holds both end spheres, so its integral is at least either one's: seen end-on
  // (the rectangle vanishes, the near cap hides the rest) and where one cap holds the lobe. The
  // larger cap, not the nearer one: seen broadside both are equally far, and rounding picked one
  // (a cap in the lobe or one in its tail: up to 32% between orientations of the same scene).
  vec3 Fcap = mix(F1, F2, bvec3(dot(F2, F2) > dot(F1, F1)));
  return mix(F, Fcap, bvec3(dot(F, F) < dot(Fcap, Fcap)));
}

// Vector form factor (cosine space) of the capsule under the LTC l: segment p1 -> p2 relative to
// the shading point (outside the capsule), radius r.
vec3 ltcCapsuleFormFactor(Ltc l, vec3 p1, vec3 p2, float r) {
  vec3 w = capsuleHalfWidth(p1, p2, r);
  // Wound counter-clockwise as seen from the origin, in world space and so in cosine space (a
  // linear map of positive determinant keeps the orientation): with w along p1 x (p2 - p1), the
  // triple product of p1 - w, p2 - w, p2 + w is 2 (p1 x p2).w >= 0. A test of F against the
  // capsule's direction in cosine space picked the side instead, and failed where the map's
  // stretch shows the rectangle nearly edge-on (grazing views: the sign flipped with the scene's
  // orientation, docs/lights.md).
  vec3 F = quadFormFactor(ltcToCosine(l, p1 - w), ltcToCosine(l, p2 - w), ltcToCosine(l, p2 + w),
                          ltcToCosine(l, p1 + w));
  return ltcCapsuleWithCaps(l, F, ltcSphereFormFactor(l, p1, r), ltcSphereFormFactor(l, p2, r),
                            p1, p2, r);
}

// Whether the capsule of segment p1 -> p2 (relative to the shading point) and radius r holds the
// shading point: the segment's closest point within r.
bool capsuleHoldsOrigin(vec3 p1, vec3 p2, float r) {
  vec3 a = p2 - p1;
  float u = clamp(-dot(p1, a) / max(dot(a, a), 1e-30f), 0.0f, 1.0f);
  vec3 q = p1 + a * u;
  return dot(q, q) <= r * r;
}

// Whether the capsule (p1, p2, r relative to the shading point) crosses the plane of the surface
// of normal N, the shading point outside it: ltcCapsuleAboveFormFactor's case.
bool ltcCapsuleStraddles(vec3 N, vec3 p1, vec3 p2, float r) {
  float h1 = dot(N, p1);
  float h2 = dot(N, p2);
  return min(h1, h2) < r && max(h1, h2) > -r && !capsuleHoldsOrigin(p1, p2, r);
}

// The part of the capsule above the surface of normal N (a capsule straddling it, as the sphere's
// case above: the LTC leaks below the surface): the facing rectangle clipped at the surface's
// plane in world space (Sutherland-Hodgman against one plane: the edges' parts above, closed
// along the plane), each end sphere's part above (ltcSphereAboveFormFactor), combined as the
// whole capsule's.
vec3 ltcCapsuleAboveFormFactor(Ltc l, vec3 N, vec3 p1, vec3 p2, float r) {
  vec3 w = capsuleHalfWidth(p1, p2, r);
  vec3 q0 = p1 - w;
  vec3 q1 = p2 - w;
  vec3 q2 = p2 + w;
  vec3 q3 = p1 + w;  // wound as ltcCapsuleFormFactor's
  float h0 = dot(N, q0);
  float h1 = dot(N, q1);
  float h2 = dot(N, q2);
  float h3 = dot(N, q3);
  vec3 c0 = ltcToCosine(l, q0);
  vec3 c1 = ltcToCosine(l, q1);
  vec3 c2 = ltcToCosine(l, q2);
  vec3 c3 = ltcToCosine(l, q3);
  vec3 x_down = vec3(0.0f);
  vec3 x_up = vec3(0.0f);
  vec3 F = ltcClippedEdge(c0, c1, h0, h1, x_down, x_up) + ltcClippedEdge(c1, c2, h1, h2, x_down, x_up) +
           ltcClippedEdge(c2, c3, h2, h3, x_down, x_up) + ltcClippedEdge(c3, c0, h3, h0, x_down, x_up);
  F = (F + ltcClosingEdge(x_down, x_up)) * (0.5f * INV_PI);
  float unused;
  vec3 F1 = ltcSphereAboveFormFactor(l, N, p1, r, ltcSphereFormFactor(l, p1, r), unused);
  vec3 F2 = ltcSphereAboveFormFactor(l, N, p2, r, ltcSphereFormFactor(l, p2, r), unused);
  return ltcCapsuleWithCaps(l, F, F1, F2, p1, p2, r);
}

// The integral of the LTC over the part of a straddling capsule above the surface, clipped at the
// horizon in cosine space.
float ltcCapsuleIntegralAbove(Ltc l, vec3 N, vec3 p1, vec3 p2, float r) {
  return horizonClippedIntegral(ltcCapsuleAboveFormFactor(l, N, p1, p2, r));
}

// Integral of the LTC over the capsule, clipped at the horizon in cosine space.
// Inside the capsule the whole hemisphere emits: 1, the normalized LTC's integral over it (as the
// sphere's, ltcSphereIntegral; a select). The facing rectangle seen from inside is bounded at
// 1e4 r wide (capsuleHalfWidth), nearly antipodal edges whose form factor float does not hold:
// the shading there read 1-2% of the hemisphere's (LtcLights.InsideTheCapsuleTheWholeHemisphereEmits).
float ltcCapsuleIntegral(Ltc l, vec3 p1, vec3 p2, float r) {
  float outside = horizonClippedIntegral(ltcCapsuleFormFactor(l, p1, p2, r));
  return mix(outside, 1.0f, capsuleHoldsOrigin(p1, p2, r));
}

// The same with the identity LTC about N (the clamped cosine: irradiance / pi), in world space:
// the caps' form factors are the sphere's closed form sin^2(sigma) times its direction, and the
// rectangle's Lambert's formula directly.
float capsuleCosineIntegral(vec3 N, vec3 p1, vec3 p2, float r) {
  vec3 w = capsuleHalfWidth(p1, p2, r);
  vec3 F = quadFormFactor(p1 - w, p2 - w, p2 + w, p1 + w);  // wound as ltcCapsuleFormFactor's
  vec3 a = p2 - p1;
  float d1 = dot(p1, p1);
  float d2 = dot(p2, p2);
  vec3 c1 = p1 * inversesqrt(max(d1, 1e-30f));
  vec3 c2 = p2 * inversesqrt(max(d2, 1e-30f));
  // sin^2(sigma) = r^2 / d^2 (1 inside the sphere).
  vec3 F1 = c1 * min(r * r / max(d1, 1e-30f), 1.0f);
  vec3 F2 = c2 * min(r * r / max(d2, 1e-30f), 1.0f);
  vec3 o1 = capCentroidOffset(c1, a, r * inversesqrt(max(d1 - r * r, 1e-30f)));
  vec3 o2 = capCentroidOffset(c2, -a, r * inversesqrt(max(d2 - r * r, 1e-30f)));
  float f1 = capFraction(max(dot(N, safeNormalize(c1 - o1)), 0.0f), max(dot(N, safeNormalize(c1 + o1)), 0.0f));
  float f2 = capFraction(max(dot(N, safeNormalize(c2 - o2)), 0.0f), max(dot(N, safeNormalize(c2 + o2)), 0.0f));
  F = F + F1 * f1 + F2 * f2;
  // At least either end sphere (ltcCapsuleFormFactor): the one that lights N more, so that two
  // caps equally far apart (broadside) are not told apart by rounding.
  vec3 Fcap = mix(F1, F2, bvec3(dot(F2, N) > dot(F1, N)));
  F = mix(F, Fcap, bvec3(dot(F, F) < dot(Fcap, Fcap)));
  // horizonClippedIntegral in the frame whose z is N.
  float f2n = dot(F, F);
  float inv_f = inversesqrt(max(f2n, 1e-30f));
  float f = min(f2n * inv_f, 1.0f);
  // Inside the capsule: the whole hemisphere (as ltcCapsuleIntegral).
  return mix(f * sphereHorizonFactor(dot(F, N) * inv_f, f), 1.0f, capsuleHoldsOrigin(p1, p2, r));
}

#endif

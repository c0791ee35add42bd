// The linearly transformed cosine (LTC) paths of the sphere and tube lights (Heitz et al. 2016;
// Heitz & Hill 2017; the LTC itself and its integrals: ltc.glsl, ltc_integrals.glsl), shared by
// GLSL and C++ (see halfvec/shading/glsl.hpp): the pixel's LTC and lobe magnitude, the light
// correction, and each light's LTC term. lights.glsl includes it after ShadingPoint and
// specularTerm and calls one function per term where the option selects LTC; the options
// (HV_SPHERE_SPECULAR, HV_TUBE_SPECULAR, HV_TUBE_DIFFUSE, HV_LTC_V_RATIO, HV_LTC_LIGHT_CORRECTION,
// HV_LTC_TABLE) are documented and defaulted there. Method and measurements: docs/lights.md ("LTC
// sphere and tube lights").
#ifndef HV_LTC_LIGHTS_GLSL
#define HV_LTC_LIGHTS_GLSL

#include "math.glsl"
#include "brdf.glsl"
#include "ltc.glsl"

#if HV_LTC_TABLE
// The two textures of the LTC table (ltc.glsl), sampled like the C++ side (ltc_table.hpp):
// bilinear, clamp to edge, level 0.
#ifdef HV_CPP
vec4 ltcFetch0(vec2 uv) { return ::hv::ltcTableSample(0, uv); }
vec4 ltcFetch1(vec2 uv) { return ::hv::ltcTableSample(1, uv); }
#else
layout(binding = HV_LTC_TEXTURE_UNIT0) uniform sampler2D t_ltc0;
layout(binding = HV_LTC_TEXTURE_UNIT1) uniform sampler2D t_ltc1;
vec4 ltcFetch0(vec2 uv) { return textureLod(t_ltc0, uv, 0.0f); }
vec4 ltcFetch1(vec2 uv) { return textureLod(t_ltc1, uv, 0.0f); }
#endif

// The integral over the hemisphere of the specular lobe the LTC shades, f (n.l) with the
// surface's Fresnel: n_f f0 + n_fresnel (f90 - f0) (Schlick's F = f0 + (f90 - f0)(1 - V.H)^5
// integrated against the fitted lobe, Heitz et al. 2016 section 4.3), f90 = 1, or UE4's
// saturate(50 f0.g) with HV_F_SCHLICK_F90_OCCLUSION. Other F terms get Schlick's average. With a V
// term other than the fitted height-correlated Smith, HV_LTC_V_RATIO scales it by that term over
// Smith's at the mirror direction (N.L = N.V, H = N); docs/lights.md, "Other BRDF choices".
vec3 ltcSpecularMagnitude(Surface s, float NoV, vec4 t1) {
#if HV_BRDF_F == HV_F_SCHLICK_F90_OCCLUSION
  vec3 f90 = vec3(saturate(50.0f * s.f0.y));
#else
  vec3 f90 = vec3(1.0f);
#endif
  vec3 m = s.f0 * t1.x + (f90 - s.f0) * t1.y;
#if HV_LTC_V_RATIO && HV_BRDF_V != HV_V_SMITH_GGX_CORRELATED
  m = m * (visibility(s.roughness, s.alpha, NoV, NoV, 1.0f, NoV) /
           V_SmithGGXCorrelated(s.alpha, NoV, NoV));
#endif
  return m;
}
#endif

// The pixel's LTC and the magnitude of its lobe (ShadingPoint.ltc, .ltc_spec), read from the table
// at (roughness, N.V); without the table (no light type shades its specular with an LTC) the
// identity LTC about N and 0, which no light then reads.
void ltcShadingSetup(Surface s, vec3 V, float NoV, HV_OUT(Ltc) ltc, HV_OUT(vec3) ltc_spec) {
#if HV_LTC_TABLE
  vec2 uv = ltcTableUv(s.roughness, NoV);
  ltc = makeLtc(s.N, V, s.alpha, ltcFetch0(uv));
  ltc_spec = ltcSpecularMagnitude(s, NoV, ltcFetch1(uv));
#else
  ltc = ltcIdentity(s.N);
  ltc_spec = vec3(0.0f);
#endif
}

#if HV_LTC_TABLE
#if HV_LTC_LIGHT_CORRECTION
// Solid angle of a sphere of sin^2(angular radius) = sin2: 2 pi (1 - cos sigma) = 2 pi sin^2 /
// (1 + cos), no cancellation for small spheres.
float sphereSolidAngle(float sin2) {
  return 2.0f * PI * sin2 / (1.0f + sqrt(max(1.0f - sin2, 0.0f)));
}

// The LTC modes' light correction (docs/lights.md, "Light correction"). The LTC matches the lobe's
// integral over the sphere, not its value in every direction: a light sees the lobe over its own
// cone, where the ratio lobe / LTC is anywhere from 0.5 to 3 in the lobe's flanks and tails at
// grazing views and high roughness (1.4-1.6 for a sphere of r/d 0.25 overhead, seen at N.V 0.36,
// roughness 0.5). Where both vary smoothly over the cone, the ratio of their sums at a few of its
// points is the ratio of their integrals, and the LTC's exact integral I times it is the lobe's.
// The points: two, at +-k tan(sigma) (e1 -+ e2) / sqrt(2) around the cone's axis c (e1 across the
// plane of c and N, e2 = c x e1; sin2 = sin^2(sigma)); k = 0.6, chosen on the sweep. Whether
// two points represent the light is tested on the LTC itself, whose integral is known: their
// quadrature omega (D(x1) + D(x2)) / 2 against I, and against omega D(c). Each disagreement
// u = (a - b) / (a + b) lowers the correction's weight linearly, from 1 at u = 0 to 0 at |u| = 1
// against I, and against the axis to 0 at -0.7 (the center's density above the points': the
// LTC's peak within the light) but only to 0.5 at +1 (the points' above the center's: tolerance
// 2). The constants were chosen on the sphere sweep and configurations off it (the ranges tried:
// docs/lights.md); weight 0: the LTC alone. As the light shrinks, both tests and the ratio become
// exact: the point light's limit, the lobe's own value times the solid angle. omega: the light's
// solid angle (for a capsule, a bound); the ratio is clamped to [0, 16]. The diagonal is chosen
// by the side of the plane of c and N the view is on, e1 - e2 on one side, e1 + e2 on the other,
// turning through e1 alone within HV_LTC_CORRECTION_MIRROR_BAND of that plane (|V.e1| below it):
// a configuration and its mirror image across the plane then take mirrored points. One diagonal
// for every view made them differ by up to 25% (roughness 0.75, r/d 0.5, elevation 30, views at
// azimuth +-170 degrees; LtcLights.SphereAndItsMirrorImageShadeAlike); both diagonals
// averaged cost a quarter more light pass on many_lights (docs/lights.md, "Light correction").
const float HV_LTC_CORRECTION_K = 0.6f;
const float HV_LTC_CORRECTION_INTEGRAL_TOL = 1.0f;
const float HV_LTC_CORRECTION_AXIS_TOL = 0.7f;
const float HV_LTC_CORRECTION_AXIS_TOL_POINTS = 2.0f;
const float HV_LTC_CORRECTION_MIRROR_BAND = 0.05f;
vec3 ltcCorrectionDiagonal(Surface s, ShadingPoint sp, vec3 c, vec3 along, float sin2, float omega,
                           float I, float diagonal) {
  // The offset stops at sin^2 = 0.9 (72 degrees): inside the sphere sin2 is 1, and the tests
  // below then keep the weight small.
  float s2 = min(sin2, 0.9f);
  vec3 e1;
  vec3 e2;
  tangentFrame(c, e1, e2);
  // e1 across the plane of c and N, e2 in it: a frame that turns with the scene, so the shading
  // does not depend on the world's axes. c along N (a light straight overhead) takes
  // tangentFrame's.
  vec3 a1 = cross(c, s.N);
  float l2 = dot(a1, a1);
  e1 = l2 > 1e-8f ? a1 * inversesqrt(l2) : e1;
  e2 = cross(c, e1);
  vec3 off = (HV_LTC_CORRECTION_K * 0.70710678f * sqrt(s2 / (1.0f - s2))) * (e1 - diagonal * e2) +
             along;
  vec3 L1 = normalize(c + off);
  vec3 L2 = normalize(c - off);
  vec3 f = specularTerm(s, sp, L1, 1.0f, 1.0f) + specularTerm(s, sp, L2, 1.0f, 1.0f);
  float d = ltcDensity(sp.ltc, L1) + ltcDensity(sp.ltc, L2);
  vec3 ratio = clamp(f / max(sp.ltc_spec * d, vec3(1e-30f)), vec3(0.0f), vec3(16.0f));
  float quad = 0.5f * omega * d;
  float axis = omega * ltcDensity(sp.ltc, c);
  float u_int = (quad - I) / max(quad + I, 1e-30f);
  float u_axis = (quad - axis) / max(quad + axis, 1e-30f);
  float w = saturate(1.0f - abs(u_int) * (1.0f / HV_LTC_CORRECTION_INTEGRAL_TOL)) *
            saturate(1.0f - abs(u_axis) * mix(1.0f / HV_LTC_CORRECTION_AXIS_TOL,
                                              1.0f / HV_LTC_CORRECTION_AXIS_TOL_POINTS,
                                              step(0.0f, u_axis)));
  return mix(vec3(1.0f), ratio, w);
}
vec3 ltcCorrection(Surface s, ShadingPoint sp, vec3 c, vec3 along, float sin2, float omega,
                   float I) {
  vec3 across = cross(c, s.N);
  float v_side = dot(sp.V, across) * inversesqrt(max(dot(across, across), 1e-16f));
  float diagonal = clamp(v_side * (1.0f / HV_LTC_CORRECTION_MIRROR_BAND), -1.0f, 1.0f);
  return ltcCorrectionDiagonal(s, sp, c, along, sin2, omega, I, diagonal);
}

// The lobe's far tail: a sphere many footprints off the mirror direction sees a part of the lobe
// that varies smoothly over it, but the LTC, fitted to the lobe's bulk, can be far from the lobe
// there at grazing views (the LTC with its light correction read 5-7% of the lobe's integral in
// LtcLights.FarTailAtGrazingViewsFollowsTheLobe), and the correction's weight swings from pixel
// to pixel (stripes across a glossy floor: docs/lights.md, "The far tail at grazing views").
// There the lobe's own quadrature over the sphere's solid angle replaces the LTC: the disk's
// 3-point rule, points at tan(sigma) / sqrt(2) from the center, 120 degrees apart, one toward R
// (on a disk of radius t each coordinate's second moment is t^2 / 4, which three such points
// match: exact for a lobe quadratic over the disk). The weight is 0 within HV_LTC_TAIL_START
// footprints (2 alpha + sigma, the error budget's unit) of R and 1 beyond HV_LTC_TAIL_END, smooth
// between; both chosen on the far-tail scene (samples/scenes/checks/ltc_far_tail.json) and
// checked on the sphere sweep.
const float HV_LTC_TAIL_START = 2.0f;
const float HV_LTC_TAIL_END = 3.0f;
float ltcTailWeight(Surface s, ShadingPoint sp, vec3 L, float sin2) {
  float footprint = 2.0f * s.alpha + asin(min(sqrt(sin2), 1.0f));
  float offset = acos(clamp(dot(L, sp.R), -1.0f, 1.0f)) / footprint;
  return smoothstep(HV_LTC_TAIL_START, HV_LTC_TAIL_END, offset);
}
// The lobe's mean over the sphere's cone (sin^2 sigma = sin2, center L) by those three points.
vec3 ltcTailLobeMean(Surface s, ShadingPoint sp, vec3 L, float sin2) {
  float s2 = min(sin2, 0.9f);
  float k = 0.70710678f * sqrt(s2 / (1.0f - s2));
  vec3 g = safeNormalize(sp.R - L * dot(L, sp.R));
  vec3 h = cross(L, g);
  vec3 f = specularTerm(s, sp, normalize(L + k * g), 1.0f, 1.0f) +
           specularTerm(s, sp, normalize(L + k * (-0.5f * g + 0.8660254f * h)), 1.0f, 1.0f) +
           specularTerm(s, sp, normalize(L + k * (-0.5f * g - 0.8660254f * h)), 1.0f, 1.0f);
  return f * (1.0f / 3.0f);
}
#endif

// Sphere light specular (HV_SPHERE_SPECULAR_LTC): the integral of the pixel's LTC over the
// sphere's cone times the emitter radiance L_e = I / (pi r^2) (docs/lights.md), windowed (and with
// the +1) as the falloff. Lc: the center relative to the shading point, L = Lc / |Lc|, d2 = |Lc|^2,
// falloff: distanceFalloff of the light.
vec3 ltcSphereSpecular(Surface s, ShadingPoint sp, vec3 Lc, vec3 L, float d2, float radius,
                       float falloff) {
  // L_e per unit I: falloff d^2 / (pi r^2) (= window / (pi r^2), times d^2 / (d^2 + 1) with the
  // +1; d^2 clamped as the falloff clamps it). A radius below 1e-4 d is shaded as 1e-4 d: the
  // integral then equals the LTC's density times the solid angle to 1e-4, and r = 0 is the
  // limit, not 0/0.
  float d2c = max(d2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  float r_eff = max(radius, 1e-4f * sqrt(d2c));
  float I = ltcSphereIntegral(sp.ltc, Lc, r_eff);
  vec3 specular = sp.ltc_spec * (I * falloff * d2c / (PI * r_eff * r_eff));
#if HV_LTC_LIGHT_CORRECTION
  // The lobe over the LTC at two points of the sphere's cone around its center (ltcCorrection).
  float sin2 = r_eff * r_eff / d2c;
  float omega = sphereSolidAngle(sin2);
  // Inside the sphere the integral is exact (the whole hemisphere emits): no correction there
  // (a select; LtcLights.InsideTheSphereTheWholeHemisphereEmits).
  bool inside = d2 <= r_eff * r_eff;
  specular = specular * mix(ltcCorrection(s, sp, L, vec3(0.0f), sin2, omega, I), vec3(1.0f),
                            bvec3(inside));
  // The far tail: the lobe's quadrature (ltcTailWeight). Not inside the sphere, nor for a sphere
  // that straddles the horizon, whose part above the surface the straddling correction computes
  // from this whole cone's LTC (sphereLightStraddleCorrection). Behind a branch: a GPU skips the
  // three lobe evaluations where no pixel of a wave is in the tail (llvmpipe runs them anyway,
  // at the same cost as without the branch: docs/lights.md, "The far tail by the lobe's
  // quadrature").
  float tail = inside || ltcSphereStraddles(s.N, Lc, r_eff) ? 0.0f : ltcTailWeight(s, sp, L, sin2);
  if (tail > 0.0f) {
    vec3 lobe = ltcTailLobeMean(s, sp, L, sin2) * (omega * falloff * d2c / (PI * r_eff * r_eff));
    specular = mix(specular, lobe, vec3(tail));
  }
#endif
  return specular;
}

#if HV_LTC_LIGHT_CORRECTION
// The part above the surface of a silhouette disk (tangent plane at unit distance along L,
// radius t = tan(sigma)) that the surface's horizon cuts along a chord (y0 along the disk's
// upward direction): the direction of its centroid, and its share of the disk's area. The
// centroid, not the part's middle: near the horizon the lobe grows about linearly with the height
// over it (its N.L), so its mean over the segment is its value at the segment's centroid
// (4 t / (3 pi) over the chord of a half disk, not t / 2: the tiny spheres centred on the
// horizon were 10-66% too bright with the middle).
vec3 ltcBandCentroid(vec3 N, vec3 L, float t, HV_OUT(float) share, HV_OUT(float) half_band) {
  float NoL = dot(N, L);
  vec3 up = N - L * NoL;
  float up_len = sqrt(max(dot(up, up), 1e-16f));
  float y0 = clamp(-NoL / up_len, -t, t);
  float chord = sqrt(max(t * t - y0 * y0, 0.0f));
  float area = t * t * acos(y0 / t) - y0 * chord;
  float yc = 2.0f * chord * chord * chord / (3.0f * max(area, 1e-30f));
  share = area / (PI * t * t);
  half_band = 0.5f * (t - y0);
  return normalize(L + up * (yc / up_len));
}

// The light correction's cone (ltcCorrection) over the part of a sphere straddling the horizon
// that lies above it (ltcBandCentroid): its centroid as the direction, half its height as the
// tangent of the cone's radius, and its share of the sphere's solid angle.
vec3 ltcBandCorrection(Surface s, ShadingPoint sp, vec3 L, float sin2, float I) {
  float t = sqrt(sin2 / max(1.0f - sin2, 1e-8f));
  float share;
  float half_band;
  vec3 center = ltcBandCentroid(s.N, L, t, share, half_band);
  float omega = sphereSolidAngle(sin2) * share;
  float band2 = half_band * half_band / (1.0f + half_band * half_band);
  return ltcCorrection(s, sp, center, vec3(0.0f), band2, omega, I);
}
#endif

#if HV_LTC_LIGHT_CORRECTION
// The integral of (1 + x^2)^-2 from 0 to u (odd in u).
float cauchy2Integral(float u) { return 0.5f * (u / (1.0f + u * u) + atan(u)); }

// The light correction of the part above the surface of a straddling sphere (L: toward its
// center, sin2 = sin^2(sigma), I: the LTC's exact integral over that part), which the LTC alone
// gets wrong near the horizon at grazing views (docs/lights.md, "Straddling spheres: the lobe over
// the part above"). On the tangent plane at unit distance along L the silhouette is a disk of
// radius t = tan(sigma), the horizon a chord at y0 along the disk's upward direction e_up; the
// part above is cut into HV_LTC_SEGMENT_ROWS rows of equal height (a point at (x, y) weighs its
// area over |p|^3: its solid angle). Three estimates of the lobe / LTC ratio, blended by where
// each holds:
// - `segment`: three cells of equal width per row, the lobe's sum over the LTC's at the 9 centres
//   (weighted down, as ltcCorrection, where the LTC's sum there misses I). Right where the lobe is
//   wide next to the cells: `resolved`, from the lobe at the rows' sides against their middles.
// - `rows`: at grazing views the lobe is narrow across the plane of incidence (three cells miss
//   it), but there it is GGX's D of the half vector's tilt across that plane, which grows linearly
//   with the distance from it: f(x0) / (1 + ((x - x0) / b)^2)^2 along a row (Walter et al. 2007
//   eq. 33; x0 where the row crosses the plane of N and V, b from f at x0 +- delta), integrated in
//   closed form over the row's width. Right where the rows resolve the lobe's height: a part no
//   higher than alpha, fading out at 2 alpha.
// - the band's cone (ltcBandCorrection): points about the part's centroid, for the rest; it fades
//   to no correction (the LTC alone) as the part grows from 8 to 16 alpha high, where points near
//   its centroid no longer see the lobe.
// Measured on the sphere sweep's straddling rows: docs/lights.md.
#define HV_LTC_SEGMENT_ROWS 3
const float HV_LTC_ROWS_HEIGHT = 1.0f;  // the rows' estimate is whole below this height / alpha
const float HV_LTC_BAND_HEIGHT = 8.0f;  // the band's cone is whole below this height / alpha
vec3 ltcSegmentCorrection(Surface s, ShadingPoint sp, vec3 L, float sin2, float I) {
  float t = sqrt(sin2 / max(1.0f - sin2, 1e-8f));
  float NoL = dot(s.N, L);
  vec3 up = s.N - L * NoL;
  float up_len = sqrt(max(dot(up, up), 1e-16f));
  vec3 e_up = up * (1.0f / up_len);
  vec3 e_side = cross(L, e_up);
  float y0 = clamp(-NoL / up_len, -t, t);
  float height = t - y0;
  float dy = height * (1.0f / float(HV_LTC_SEGMENT_ROWS));
  vec3 m = cross(s.N, sp.V);  // normal to the plane of incidence
  float m_side = dot(e_side, m);
  vec3 f = vec3(0.0f);        // the lobe over the cells
  float d = 0.0f;             // the LTC over the cells
  float f_mid = 0.0f;         // the lobe at the rows' middle cells
  float f_side = 0.0f;        // and at their side cells
  vec3 Q = vec3(0.0f);        // the lobe's integral over the rows
  for (int i = 0; i < HV_LTC_SEGMENT_ROWS; ++i) {
    float y = y0 + dy * (float(i) + 0.5f);
    float half_width = sqrt(max(t * t - y * y, 0.0f));
    vec3 q = L + e_up * y;
    for (int j = -1; j <= 1; ++j) {
      vec3 p = q + e_side * (half_width * (2.0f / 3.0f) * float(j));
      float inv_len = inversesqrt(dot(p, p));
      float w = (2.0f / 3.0f) * half_width * dy * inv_len * inv_len * inv_len;
      vec3 Lp = p * inv_len;
      vec3 fp = specularTerm(s, sp, Lp, w, 1.0f);
      f += fp;
      f_mid += j == 0 ? fp.y : 0.0f;
      f_side += j == 0 ? 0.0f : 0.5f * fp.y;
      d += w * ltcDensity(sp.ltc, Lp);
    }
    // The row's crossing of the plane of incidence (its middle where the row runs along it).
    float x0 = abs(m_side) > 1e-6f ? -dot(q, m) / m_side : 0.0f;
    x0 = clamp(x0, -half_width, half_width);
    float delta = max(0.25f * half_width, 1e-20f);
    vec3 p0 = q + e_side * x0;
    vec3 pa = q + e_side * (x0 + delta);
    vec3 pb = q + e_side * (x0 - delta);
    float inv0 = inversesqrt(dot(p0, p0));
    float inva = inversesqrt(dot(pa, pa));
    float invb = inversesqrt(dot(pb, pb));
    vec3 f0 = specularTerm(s, sp, p0 * inv0, inv0 * inv0 * inv0, 1.0f);
    vec3 f1 = 0.5f * (specularTerm(s, sp, pa * inva, inva * inva * inva, 1.0f) +
                      specularTerm(s, sp, pb * invb, invb * invb * invb, 1.0f));
    // (1 + (delta / b)^2)^2 = f0 / f1; a lobe no lower at x0 +- delta is flat over the row.
    float k = sqrt(max(f0.y, 1e-30f) / max(f1.y, 1e-30f));
    float b = delta * inversesqrt(max(k - 1.0f, 1e-8f));
    float row =
        b * (cauchy2Integral((half_width - x0) / b) + cauchy2Integral((half_width + x0) / b));
    Q += f0 * (min(row, 2.0f * half_width) * dy);
  }
  vec3 ratio = clamp(f / max(sp.ltc_spec * d, vec3(1e-30f)), vec3(0.0f), vec3(16.0f));
  float u_int = (d - I) / max(d + I, 1e-30f);
  vec3 segment =
      mix(vec3(1.0f), ratio, saturate(1.0f - abs(u_int) * (1.0f / HV_LTC_CORRECTION_INTEGRAL_TOL)));
  float resolved = saturate(4.0f * f_side / max(f_mid, 1e-30f) - 1.0f);
  vec3 rows = clamp(Q / max(sp.ltc_spec * I, vec3(1e-30f)), vec3(0.0f), vec3(16.0f));
  float alpha = max(s.alpha, 1e-8f);
  float w_rows = saturate(2.0f - height / (HV_LTC_ROWS_HEIGHT * alpha)) * (1.0f - resolved);
  vec3 band = mix(ltcBandCorrection(s, sp, L, sin2, I), vec3(1.0f),
                  saturate(height / (HV_LTC_BAND_HEIGHT * alpha) - 1.0f));
  return mix(mix(band, segment, resolved), rows, w_rows);
}
#endif

// ltcSphereSpecular for a sphere that straddles the surface's horizon (ltcSphereSpecularStraddles
// below): the part below the surface cut off (ltcSphereIntegralAbove), and the light correction
// taken over the part above (ltcSegmentCorrection).
vec3 ltcSphereSpecularAbove(Surface s, ShadingPoint sp, vec3 Lc, vec3 L, float d2, float radius,
                            float falloff) {
  float d2c = max(d2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  float r_eff = max(radius, 1e-4f * sqrt(d2c));
  float I = ltcSphereIntegralAbove(sp.ltc, s.N, Lc, r_eff, ltcSphereFormFactor(sp.ltc, Lc, r_eff));
  vec3 specular = sp.ltc_spec * (I * falloff * d2c / (PI * r_eff * r_eff));
#if HV_LTC_LIGHT_CORRECTION
  specular = specular * ltcSegmentCorrection(s, sp, L, r_eff * r_eff / d2c, I);
#endif
  return specular;
}

// ltcSphereSpecularAbove - ltcSphereSpecular for a straddling sphere, the cone's form factor
// computed once (the tiled light pass's second part, lights.glsl).
vec3 ltcSphereSpecularCut(Surface s, ShadingPoint sp, vec3 Lc, vec3 L, float d2, float radius,
                          float falloff) {
  float d2c = max(d2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  float r_eff = max(radius, 1e-4f * sqrt(d2c));
  vec3 F = ltcSphereFormFactor(sp.ltc, Lc, r_eff);
  float I_whole = horizonClippedIntegral(F);
  float I_above = ltcSphereIntegralAbove(sp.ltc, s.N, Lc, r_eff, F);
  vec3 scale = sp.ltc_spec * (falloff * d2c / (PI * r_eff * r_eff));
#if HV_LTC_LIGHT_CORRECTION
  float sin2 = r_eff * r_eff / d2c;
  return scale * (I_above * ltcSegmentCorrection(s, sp, L, sin2, I_above) -
                  I_whole * ltcCorrection(s, sp, L, vec3(0.0f), sin2, sphereSolidAngle(sin2),
                                          I_whole));
#else
  return scale * (I_above - I_whole);
#endif
}

// Whether ltcSphereSpecular leaves out what ltcSphereSpecularAbove cuts off: the sphere, at the
// radius both shade it with, straddles the horizon of N from outside.
bool ltcSphereSpecularStraddles(vec3 N, vec3 Lc, float d2, float radius) {
  float d2c = max(d2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  return ltcSphereStraddles(N, Lc, max(radius, 1e-4f * sqrt(d2c)));
}
#endif

#if HV_TUBE_DIFFUSE == HV_TUBE_DIFFUSE_LTC || HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC
// The capsule's radius as the LTC paths shade it: a radius below 1e-4 d is shaded as 1e-4 d (the
// line light's limit instead of 0/0); dp2c: the squared distance to the closest segment point,
// clamped as the falloff clamps it (ltcCapsuleDist2).
float ltcCapsuleDist2(float dp2, float radius) {
  return max(dp2, max(radius * radius, HV_MIN_LIGHT_DIST2));
}
float ltcCapsuleRadius(float radius, float dp2c) { return max(radius, 1e-4f * sqrt(dp2c)); }
// Emitter radiance per unit I (docs/lights.md): window / (pi r (r + len / 2)), times
// d^2 / (d^2 + 1) with the +1 (d: the closest segment point).
float ltcCapsuleEmit(float window, float dp2c, float r_eff, float len) {
  return window * (dp2c / (dp2c + float(HV_FALLOFF_PLUS_ONE))) /
         (PI * r_eff * (r_eff + 0.5f * len));
}
#endif

#if HV_TUBE_DIFFUSE == HV_TUBE_DIFFUSE_LTC
// Tube light diffuse irradiance per unit I (HV_TUBE_DIFFUSE_LTC): pi L_e times the capsule's
// integral of the clamped cosine (the identity LTC). L0, L1: the segment's ends relative to the
// shading point; dp2: squared distance to its closest point; window: the falloff window there.
float ltcTubeIrradiance(Surface s, vec3 L0, vec3 L1, float dp2, float radius, float len,
                        float window) {
  float dp2c = ltcCapsuleDist2(dp2, radius);
  float r_eff = ltcCapsuleRadius(radius, dp2c);
  return ltcCapsuleEmit(window, dp2c, r_eff, len) * PI * capsuleCosineIntegral(s.N, L0, L1, r_eff);
}
#endif

#if HV_LTC_TABLE && HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC
// Tube light specular (HV_TUBE_SPECULAR_LTC): the pixel's LTC integrated over the capsule, times
// the emitter radiance L_e = I / (pi r^2 + pi r len / 2) (docs/lights.md). Lc: the segment's
// center, Ld = L1 - L0, and the rest as ltcTubeIrradiance. above: over the part of the capsule
// above the surface (a capsule straddling the horizon, ltcCapsuleAboveFormFactor), else over the
// whole capsule; the callers pass a constant, so each compiles one of the two.
vec3 ltcTubeSpecularOver(Surface s, ShadingPoint sp, vec3 Lc, vec3 Ld, vec3 L0, vec3 L1,
                         float dp2, float radius, float len, float window, bool above) {
  float dp2c = ltcCapsuleDist2(dp2, radius);
  float r_eff = ltcCapsuleRadius(radius, dp2c);
  float I = above ? ltcCapsuleIntegralAbove(sp.ltc, s.N, L0, L1, r_eff)
                  : ltcCapsuleIntegral(sp.ltc, L0, L1, r_eff);
  vec3 specular = sp.ltc_spec * (ltcCapsuleEmit(window, dp2c, r_eff, len) * I);
#if HV_LTC_LIGHT_CORRECTION
  // As the sphere's (ltcSphereSpecular), around the capsule's center, its two points also
  // spread along the axis at +-1/sqrt(3) of the half-length (the two-point Gauss rule of a
  // segment), with the capsule's solid angle (at most (pi r^2 + 2 r len) / d^2, d the closest
  // segment point) and integral. len = 0 gives the sphere's correction exactly. Over the part
  // above the surface: around the centroid of the cross-section's part above it, with that
  // part's share of the solid angle (ltcBandCentroid, as a straddling sphere's).
  float sin2 = r_eff * r_eff / dp2c;
  float omega = sphereSolidAngle(sin2) + 2.0f * r_eff * len / dp2c;
  float inv_lc = inversesqrt(max(dot(Lc, Lc), 1e-30f));
  vec3 c = Lc * inv_lc;
  if (above) {
    float share;
    float half_band;
    c = ltcBandCentroid(s.N, c, sqrt(sin2 / max(1.0f - sin2, 1e-8f)), share, half_band);
    omega *= share;
  }
  // Inside the capsule the integral is exact (ltcCapsuleIntegral): no correction there.
  specular = specular * mix(ltcCorrection(s, sp, c, (0.57735027f * 0.5f * inv_lc) * Ld, sin2,
                                          omega, I),
                            vec3(1.0f), bvec3(capsuleHoldsOrigin(L0, L1, r_eff)));
#endif
  return specular;
}

// Whether the capsule, at the radius the LTC shades it with, straddles the surface's horizon
// (ltcCapsuleStraddles): the pairs ltcTubeSpecularOver(..., true) is for.
bool ltcTubeSpecularStraddles(Surface s, vec3 L0, vec3 L1, float dp2, float radius) {
  return ltcCapsuleStraddles(s.N, L0, L1, ltcCapsuleRadius(radius, ltcCapsuleDist2(dp2, radius)));
}

// The tube's specular, over the part above the surface where it straddles the horizon.
vec3 ltcTubeSpecular(Surface s, ShadingPoint sp, vec3 Lc, vec3 Ld, vec3 L0, vec3 L1, float dp2,
                     float radius, float len, float window) {
  if (ltcTubeSpecularStraddles(s, L0, L1, dp2, radius)) {
    return ltcTubeSpecularOver(s, sp, Lc, Ld, L0, L1, dp2, radius, len, window, true);
  }
  return ltcTubeSpecularOver(s, sp, Lc, Ld, L0, L1, dp2, radius, len, window, false);
}
#endif

#endif

// Split-sum prefiltering (Karis 2013, "Real Shading in Unreal Engine 4", eqs. 6-8).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/constants.hpp>

#include "halfvec/ibl/ibl.hpp"
#include "halfvec/ibl/ibl_math.hpp"
#include "halfvec/core/parallel.hpp"
#include "halfvec/shading/brdf.hpp"

namespace hv {
namespace {

constexpr float kPi = glm::pi<float>();

// PCG-style integer hash -> [0, 1), decorrelates the per-texel rotation of the sample pattern.
float hash01(uint32_t a, uint32_t b, uint32_t c) {
  uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ (c + 0x165667B1u) * 0xC2B2AE3Du;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return float(h >> 8) * (1.0f / 16777216.0f);
}

// Pairs (output texel, source texel) a mip may take to be convolved by quadrature instead of
// importance-sampled: 200 M (a 256 cube's mip 2, 64x64 faces over a 32x32 source) takes about a
// second on two cores, once per environment (the bake is cached).
constexpr double kQuadratureBudget = 200e6;

// Half-width (radians) of the reflected-direction lobe of Karis eq. 7 with n = v: the angle of
// L = reflect(-N, H) where D_GGX(H) falls to half its peak, i.e. twice that of H. The peak-
// normalized D is alpha^4 / ((alpha^2 - 1) c^2 + 1)^2 (c = NoH); it reaches 1/2 at
// c^2 = (1 - sqrt(2) alpha^2) / (1 - alpha^2), or never (alpha^2 >= 1/sqrt(2): the whole
// hemisphere).
float lobeHalfWidth(float alpha) {
  const float a2 = alpha * alpha;
  if (a2 >= 0.70710678f) return 0.5f * kPi;
  const float c2 = (1.0f - 1.41421356f * a2) / (1.0f - a2);
  return std::min(2.0f * std::acos(std::sqrt(std::clamp(c2, 0.0f, 1.0f))), 0.5f * kPi);
}

// The source mip for the quadrature of a lobe of half-width `half` (radians): the largest texels
// no wider than the half-width (a face spans pi/2), at least 16 texels a face. Smooth
// radiance needs no more (the weights are normalized by the same quadrature, so a constant is
// exact); bright spots are refined below.
int quadratureSourceMip(const CubeMapF& source, float half) {
  int m = 0;
  while (m + 1 < source.mipCount() && source.mipSize(m + 1) >= 16 &&
         0.5f * kPi / float(source.mipSize(m + 1)) <= half) {
    ++m;
  }
  return m;
}

// A source direction of the quadrature: texel center, radiance times solid angle, solid angle.
struct QuadTexel {
  glm::vec3 dir, radiance_omega;
  float omega;
};

// The texels of source mip `sm`, except that a texel carrying more than kRefineEnergy times the
// mean energy (radiance x solid angle; a sun, a studio light) is replaced by its children up to
// kRefineLevels mips finer: the kernel is then evaluated where the bright source really is, not
// at the center of a coarse texel (at the shoulder of a lobe a position error of half a coarse
// texel changes D by tens of percent).
constexpr float kRefineEnergy = 16.0f;
constexpr int kRefineLevels = 3;
std::vector<QuadTexel> quadratureTexels(const CubeMapF& source, int sm) {
  const int S = source.mipSize(sm);
  auto energy = [&](int m, int f, int x, int y) {
    const int n = source.mipSize(m);
    return glsl::dot(source.at(m, f, x, y), glm::vec3(0.2126f, 0.7152f, 0.0722f)) *
           cubeTexelSolidAngle(x, y, n);
  };
  double total = 0.0;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) total += double(energy(sm, f, x, y));
  const float threshold = float(kRefineEnergy * total / (6.0 * S * S));
  const int fine = std::max(sm - kRefineLevels, 0), k = 1 << (sm - fine);
  std::vector<QuadTexel> out;
  auto add = [&](int m, int f, int x, int y) {
    const int n = source.mipSize(m);
    const float o = cubeTexelSolidAngle(x, y, n);
    out.push_back({cubeTexelDirection(f, x, y, n), source.at(m, f, x, y) * o, o});
  };
  for (int f = 0; f < 6; ++f) {
    for (int y = 0; y < S; ++y) {
      for (int x = 0; x < S; ++x) {
        if (fine == sm || energy(sm, f, x, y) <= threshold) {
          add(sm, f, x, y);
          continue;
        }
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < k; ++i) add(fine, f, x * k + i, y * k + j);
      }
    }
  }
  return out;
}

// Karis 2013 eq. 7 with n = v = r computed exactly, as a quadrature over source texels instead of
// importance samples: every source direction L with NoL > 0 weighs D(h) NoL dOmega (h the half
// vector of N and L, NoH = sqrt((1 + NoL) / 2)), the same weights as the sampled estimator's
// limit (samples L with pdf D(h) / 4, weighted by NoL). Deterministic and continuous in N: no
// noise from texel to texel, so a bright sun cannot leave a blotch pattern on rough metals.
void convolveMip(const std::vector<QuadTexel>& texels, const CubeMapF& source, float alpha, int m,
                 CubeMapF& out, int threads) {
  const int s = out.mipSize(m);
  detail::parallelFor(6 * s, threads, [&](int row) {
    const int face = row / s, y = row % s;
    for (int x = 0; x < s; ++x) {
      const glm::vec3 N = cubeTexelDirection(face, x, y, s);
      glm::dvec3 sum(0.0);
      double wsum = 0.0;
      for (const QuadTexel& t : texels) {
        const float NoL = glm::dot(N, t.dir);
        if (NoL <= 0.0f) continue;
        const float w = glsl::D_GGX(alpha, std::sqrt(0.5f * (1.0f + NoL))) * NoL;
        sum += glm::dvec3(t.radiance_omega * w);
        wsum += double(w * t.omega);
      }
      out.at(m, face, x, y) = wsum > 0.0 ? glm::vec3(sum / wsum) : source.sample(N, 0);
    }
  });
}

// One GGX importance sample around N = +Z with the quantities the prefilter needs.
struct LocalSample {
  glm::vec3 h;   // half vector in tangent space (z = NoH)
  float weight;  // NoL (Karis eq. 7 weighting)
  float lod;     // source mip by filtered importance sampling
};

}  // namespace

CubeMapF prefilterRadiance(const CubeMapF& source, int samples, int min_mip_size, int threads,
                           bool progress) {
  if (source.size <= 0 || source.mipCount() < 1)
    throw IblError("prefilterRadiance: empty source cube");
  samples = std::max(samples, 1);
  min_mip_size = std::clamp(min_mip_size, 1, source.size);
  int mips = 1;
  while ((source.size >> mips) >= min_mip_size) ++mips;
  CubeMapF out = makeCubeMap(source.size, mips);
  out.levels[0] = source.levels[0];  // mip 0: the unfiltered environment (roughness 0)
  const float max_mip = float(mips - 1);
  // Solid angle of one texel of the source's mip 0 (mean over the cube).
  const float omega_p = 4.0f * kPi / (6.0f * float(source.size) * float(source.size));

  for (int m = 1; m < mips; ++m) {
    const float roughness = glsl::mipToRoughness(float(m), max_mip);
    const float alpha = roughness * roughness;
    const int s = out.mipSize(m);
    const int sm = quadratureSourceMip(source, lobeHalfWidth(alpha));
    const double pairs =
        36.0 * double(s) * double(s) * double(source.mipSize(sm)) * double(source.mipSize(sm));
    if (pairs <= kQuadratureBudget) {
      const std::vector<QuadTexel> texels = quadratureTexels(source, sm);
      if (progress)
        std::fprintf(stderr,
                     "[ibl] prefilter mip %d/%d (%dx%d, roughness %.3f, quadrature over %zu texels "
                     "of the %dx%d mip, bright ones refined)\n",
                     m, mips - 1, s, s, double(roughness), texels.size(), source.mipSize(sm),
                     source.mipSize(sm));
      convolveMip(texels, source, alpha, m, out, threads);
      continue;
    }
    if (progress)
      std::fprintf(stderr, "[ibl] prefilter mip %d/%d (%dx%d, roughness %.3f, %d samples)\n", m,
                   mips - 1, s, s, double(roughness), samples);
    // Karis 2013 eq. 7 with n = v = r: samples are the same around every texel up to a rotation,
    // so they are drawn once in tangent space. Krivanek & Colbert 2008 (GPU Gems 3 ch. 20,
    // "GPU-Based Importance Sampling", eqs. 13-14): read the source at the mip whose texel solid
    // angle matches the sample's, omega_s = 1 / (N pdf), pdf = D(h) NoH / (4 VoH) (VoH = NoH when
    // v = n); +1 mip of bias as in the paper for a smoother result.
    std::vector<LocalSample> pattern;
    pattern.reserve(size_t(samples));
    for (int i = 0; i < samples; ++i) {
      const glm::vec2 xi = glsl::hammersley(glsl::uint(i), glsl::uint(samples));
      const glm::vec3 h = glsl::importanceSampleGGX(xi, alpha, glm::vec3(0.0f, 0.0f, 1.0f));
      const float NoH = h.z;
      const float NoL = 2.0f * NoH * NoH - 1.0f;  // L = 2 (V.H) H - V with V = N
      if (NoL <= 0.0f) continue;
      const float pdf = glsl::pdfGGX(alpha, NoH) / (4.0f * NoH);  // pdf of L, VoH = NoH
      const float omega_s = 1.0f / (float(samples) * pdf);
      const float lod = std::max(0.5f * std::log2(omega_s / omega_p) + 1.0f, 0.0f);
      pattern.push_back({h, NoL, lod});
    }
    detail::parallelFor(6 * s, threads, [&](int row) {
      const int face = row / s, y = row % s;
      for (int x = 0; x < s; ++x) {
        const glm::vec3 N = cubeTexelDirection(face, x, y, s);
        // Tangent frame, rotated about N by a per-texel random angle: the fixed Hammersley
        // pattern turns into noise instead of repeating ghost copies of a bright sun.
        const glm::vec3 up = std::abs(N.y) < 0.999f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        glm::vec3 T = glm::normalize(glm::cross(up, N));
        glm::vec3 B = glm::cross(N, T);
        const float phi = 2.0f * kPi * hash01(uint32_t(m), uint32_t(face * s + y), uint32_t(x));
        const float c = std::cos(phi), sn = std::sin(phi);
        const glm::vec3 T2 = c * T + sn * B, B2 = -sn * T + c * B;
        glm::vec3 sum(0.0f);
        float wsum = 0.0f;
        for (const LocalSample& p : pattern) {
          const glm::vec3 H = p.h.x * T2 + p.h.y * B2 + p.h.z * N;
          const glm::vec3 L = 2.0f * p.h.z * H - N;
          sum += source.sampleLod(L, p.lod) * p.weight;
          wsum += p.weight;
        }
        out.at(m, face, x, y) = wsum > 0.0f ? sum / wsum : source.sample(N, 0);
      }
    });
  }
  return out;
}

glm::vec2 integrateEnvBrdfAt(float NoV, float roughness, int samples, const BrdfConfig& brdf) {
  // Karis 2013 eq. 8 / IntegrateBRDF: with V in the tangent plane (x, z), N = +Z,
  //   scale = 1/N sum (1 - Fc) G_vis,  bias = 1/N sum Fc G_vis,  Fc = (1 - VoH)^5,
  //   G_vis = G VoH / (NoH NoV) = 4 V NoL VoH / NoH  (V = G / (4 NoL NoV), the visibility term).
  // V comes from the configured term at alpha = roughness^2 with no Disney remap (Karis: the
  // remap is for analytic lights only); the default SchlickGGX is k = alpha / 2.
  NoV = std::clamp(NoV, glsl::HV_MIN_NOV, 1.0f);
  const float alpha =
      std::max(roughness * roughness, glsl::HV_MIN_ROUGHNESS * glsl::HV_MIN_ROUGHNESS);
  const glm::vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
  const glm::vec3 N(0.0f, 0.0f, 1.0f);
  double a = 0.0, b = 0.0;
  for (int i = 0; i < samples; ++i) {
    const glm::vec2 xi = glsl::hammersley(glsl::uint(i), glsl::uint(samples));
    const glm::vec3 H = glsl::importanceSampleGGX(xi, alpha, N);
    const float VoH = glm::dot(V, H);
    const glm::vec3 L = 2.0f * VoH * H - V;
    const float NoL = glsl::saturate(L.z);
    const float NoH = glsl::saturate(H.z);
    if (NoL <= 0.0f || VoH <= 0.0f) continue;
    const float vis = evalVForAlpha(brdf, alpha, NoV, NoL, NoH, VoH);
    const float g_vis = 4.0f * vis * NoL * VoH / std::max(NoH, 1e-8f);
    const float fc = glsl::pow5(1.0f - VoH);
    a += double((1.0f - fc) * g_vis);
    b += double(fc * g_vis);
  }
  return glm::vec2(float(a / samples), float(b / samples));
}

std::vector<glm::vec2> integrateEnvBrdf(int size, int samples, int threads,
                                        const BrdfConfig& brdf) {
  std::vector<glm::vec2> table(size_t(size) * size_t(size));
  detail::parallelFor(size, threads, [&](int row) {
    const float roughness = (float(row) + 0.5f) / float(size);
    for (int col = 0; col < size; ++col) {
      const float NoV = (float(col) + 0.5f) / float(size);
      table[size_t(row) * size_t(size) + size_t(col)] =
          integrateEnvBrdfAt(NoV, roughness, samples, brdf);
    }
  });
  return table;
}

glm::vec2 lookupEnvBrdf(const std::vector<glm::vec2>& table, int size, float NoV, float roughness) {
  const float fx = std::clamp(NoV * float(size) - 0.5f, 0.0f, float(size - 1));
  const float fy = std::clamp(roughness * float(size) - 0.5f, 0.0f, float(size - 1));
  const int x0 = int(fx), y0 = int(fy);
  const int x1 = std::min(x0 + 1, size - 1), y1 = std::min(y0 + 1, size - 1);
  const float tx = fx - float(x0), ty = fy - float(y0);
  auto at = [&](int x, int y) { return table[size_t(y) * size_t(size) + size_t(x)]; };
  return glm::mix(glm::mix(at(x0, y0), at(x1, y0), tx), glm::mix(at(x0, y1), at(x1, y1), tx), ty);
}

}  // namespace hv

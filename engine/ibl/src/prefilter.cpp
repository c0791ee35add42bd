// Split-sum prefiltering (Karis 2013, "Real Shading in Unreal Engine 4", eqs. 6-8).
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

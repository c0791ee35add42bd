#include "halfvec/eval/ltc_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "halfvec/core/parallel.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::eval {

namespace {

namespace g = hv::glsl;

// The frame of a cell: N = +z, V in the xz plane on the +x side.
glm::vec3 cellView(float NoV) {
  return glm::vec3(std::sqrt(std::max(0.0f, 1.0f - NoV * NoV)), 0.0f, NoV);
}

float cellAlpha(float roughness) {
  const float r = std::clamp(roughness, g::HV_MIN_ROUGHNESS, 1.0f);
  return r * r;
}

// f (n.l) with F = 1 for the fitted lobe: GGX D (with |N x H|^2, as the engine) x height-
// correlated Smith V x cos.
double lobe(float alpha, const glm::vec3& V, const glm::vec3& l) {
  if (l.z <= 0.0f) return 0.0;
  const glm::vec3 H = g::safeNormalize(V + l);
  const float sin2 = H.x * H.x + H.y * H.y;
  const float NoV = std::max(V.z, g::HV_MIN_NOV);
  return double(g::D_GGX(alpha, H.z, sin2)) * g::V_SmithGGXCorrelated(alpha, NoV, l.z) * l.z;
}

// Solid-angle pdf of l = reflect(-V, H) for H from sampleGGXVNDF.
double vndfPdf(float alpha, const glm::vec3& V, const glm::vec3& l) {
  const glm::vec3 H = g::safeNormalize(V + l);
  const float VoH = glm::dot(V, H);
  if (VoH <= 0.0f || H.z <= 0.0f) return 0.0;
  return double(g::pdfGGXVNDF(V, H, alpha)) / (4.0 * VoH);
}

// The weight f (n.l) / pdf of a direction l = reflect(-V, H), H from sampleGGXVNDF (N.V = nov,
// clamped as the lobe clamps it; G1 = G1(V)): D V_corr (n.l) / (G1(V) D / (4 N.V)) =
// 4 N.V V_corr (n.l) / G1(V).
double lobeOverVndfPdf(float alpha, float nov, float G1, float NoL) {
  return 4.0 * nov * g::V_SmithGGXCorrelated(alpha, nov, NoL) * NoL / G1;
}

glm::vec2 hammersley2(int i, int n) {
  return g::hammersley(uint32_t(i), uint32_t(n));
}

// The LTC of the fit's parameters (the axis's d_x, d_z >= 0; the table stores its tilt instead,
// ltc.glsl's ltcTiltFromAxis).
g::Ltc cellLtc(const LtcParams& p, float alpha, const glm::vec3& V) {
  return g::makeLtcAxis(glm::vec3(0.0f, 0.0f, 1.0f), V, alpha, glm::vec3(p.ax, p.ay, p.sk), p.dx,
                        std::sqrt(std::max(1.0f - p.dx * p.dx, 0.0f)));
}

// M (up to a positive factor) of an LTC: the inverse of its rows alpha M^-1.
glm::mat3 ltcMatrix(const g::Ltc& l) {
  return glm::inverse(glm::transpose(glm::mat3(l.i0, l.i1, l.i2)));
}

// The fixed samples of one cell: directions from the lobe (with the lobe's value and pdf, which
// do not depend on the parameters) and the cosine samples the LTC maps.
struct CellSamples {
  float alpha = 0.0f;
  glm::vec3 V;
  double norm = 1.0;
  std::vector<glm::vec3> lobe_dirs;
  std::vector<double> lobe_val, lobe_pdf;
  std::vector<glm::vec3> cosine_dirs;
};

CellSamples makeSamples(float roughness, float NoV, double norm, int per_dim) {
  CellSamples s;
  s.alpha = cellAlpha(roughness);
  s.V = cellView(NoV);
  s.norm = norm;
  const int n = per_dim * per_dim;
  for (int i = 0; i < n; ++i) {
    const glm::vec2 u = hammersley2(i, n);
    const glm::vec3 H = g::sampleGGXVNDF(s.V, s.alpha, u);
    const glm::vec3 l = glm::reflect(-s.V, H);
    s.lobe_dirs.push_back(l);
    s.lobe_val.push_back(lobe(s.alpha, s.V, l) / norm);
    s.lobe_pdf.push_back(vndfPdf(s.alpha, s.V, l));
    // Cosine samples: the same points with the coordinates swapped (decorrelated from the lobe's).
    s.cosine_dirs.push_back(g::sampleCosineHemisphere(glm::vec2(u.y, u.x)));
  }
  return s;
}

// integral |D_ltc - f cos / n_f|^power over the sphere (MIS estimate; see ltcFitError).
double fitErrorP(const CellSamples& s, const LtcParams& p, double power) {
  const g::Ltc l = cellLtc(p, s.alpha, s.V);
  const glm::mat3 M = ltcMatrix(l);
  const double n = double(s.lobe_dirs.size());
  double e = 0.0;
  for (size_t k = 0; k < s.lobe_dirs.size(); ++k) {
    // A lobe sample: |D - f| / (n (p_lobe + p_ltc)).
    const double d = g::ltcDensity(l, s.lobe_dirs[k]);
    const double pl = s.lobe_pdf[k];
    if (pl + d > 0.0) e += std::pow(std::abs(d - s.lobe_val[k]), power) / (n * (pl + d));
    // An LTC sample: its pdf is D itself.
    const glm::vec3 w = glm::normalize(M * s.cosine_dirs[k]);
    const double dw = g::ltcDensity(l, w);
    const double fw = lobe(s.alpha, s.V, w) / s.norm;
    const double pw = vndfPdf(s.alpha, s.V, w);
    if (pw + dw > 0.0) e += std::pow(std::abs(dw - fw), power) / (n * (pw + dw));
  }
  return e;
}
double fitError(const CellSamples& s, const LtcParams& p) {
  return fitErrorP(s, p, 1.0);
}

// Nelder-Mead over x = (ln a_x, ln a_y, s, tilt) (Nelder & Mead 1965; standard coefficients 1, 2,
// 1/2, 1/2), tilt in radians from the lobe's mean direction. Returns the best point; `iterations`
// gets the count.
template <class F>
std::array<double, 4> nelderMead(F&& f, std::array<double, 4> x0, int max_iter, int& iterations) {
  using P = std::array<double, 4>;
  constexpr int D = 4;
  std::array<P, D + 1> x;
  std::array<double, D + 1> fx;
  x[0] = x0;
  const double step[D] = {0.15, 0.15, 0.1, 0.05};
  for (int k = 0; k < D; ++k) {
    x[k + 1] = x0;
    x[k + 1][k] += step[k];
  }
  for (int k = 0; k <= D; ++k) fx[k] = f(x[k]);
  auto lerp = [](const P& a, const P& b, double t) {
    P r;
    for (int k = 0; k < D; ++k) r[k] = a[k] + (b[k] - a[k]) * t;
    return r;
  };
  int it = 0;
  for (; it < max_iter; ++it) {
    std::array<int, D + 1> order = {0, 1, 2, 3, 4};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return fx[a] < fx[b]; });
    std::array<P, D + 1> xs;
    std::array<double, D + 1> fs;
    for (int k = 0; k <= D; ++k) {
      xs[k] = x[order[k]];
      fs[k] = fx[order[k]];
    }
    x = xs;
    fx = fs;
    // Converged: the simplex's values within 1e-7 of the best (relative) and its size below 1e-5.
    double size = 0.0;
    for (int k = 1; k <= D; ++k)
      for (int c = 0; c < D; ++c) size = std::max(size, std::abs(x[k][c] - x[0][c]));
    if (fx[D] - fx[0] <= 1e-7 * (fx[0] + 1e-6) && size < 1e-5) break;
    P centroid{};
    for (int k = 0; k < D; ++k)
      for (int c = 0; c < D; ++c) centroid[c] += x[k][c] / double(D);
    const P xr = lerp(centroid, x[D], -1.0);
    const double fr = f(xr);
    if (fr < fx[0]) {
      const P xe = lerp(centroid, x[D], -2.0);
      const double fe = f(xe);
      if (fe < fr) {
        x[D] = xe;
        fx[D] = fe;
      } else {
        x[D] = xr;
        fx[D] = fr;
      }
    } else if (fr < fx[D - 1]) {
      x[D] = xr;
      fx[D] = fr;
    } else {
      const bool outside = fr < fx[D];
      const P xc = lerp(centroid, outside ? xr : x[D], 0.5);
      const double fc = f(xc);
      if (fc < std::min(fr, fx[D])) {
        x[D] = xc;
        fx[D] = fc;
      } else {  // shrink toward the best
        for (int k = 1; k <= D; ++k) {
          x[k] = lerp(x[0], x[k], 0.5);
          fx[k] = f(x[k]);
        }
      }
    }
  }
  iterations = it;
  int best = int(std::min_element(fx.begin(), fx.end()) - fx.begin());
  return x[best];
}

LtcParams toParams(const std::array<double, 4>& x, float dx0) {
  LtcParams p;
  const double th = std::asin(std::clamp(double(dx0), -1.0, 1.0)) + x[3];
  const float dx = float(std::sin(std::clamp(th, -1.5707, 1.5707)));
  p.ax = float(std::exp(x[0]));
  p.ay = float(std::exp(x[1]));
  p.sk = float(x[2]);
  p.dx = dx;
  return p;
}

}  // namespace

LtcLobeMoments integrateLtcLobe(float roughness, float NoV, int per_dim) {
  const float alpha = cellAlpha(roughness);
  const glm::vec3 V = cellView(NoV);
  const int n = per_dim * per_dim;
  const float nov = std::max(V.z, g::HV_MIN_NOV);
  const float G1 = g::G1_SmithGGX(alpha, nov);
  double norm = 0.0, fresnel = 0.0;
  glm::dvec3 mean(0.0);
  for (int i = 0; i < n; ++i) {
    const glm::vec3 H = g::sampleGGXVNDF(V, alpha, hammersley2(i, n));
    const glm::vec3 l = glm::reflect(-V, H);
    if (l.z <= 0.0f) continue;
    const double w = lobeOverVndfPdf(alpha, nov, G1, l.z);
    const double VoH = std::clamp(double(glm::dot(V, H)), 0.0, 1.0);
    norm += w;
    fresnel += w * std::pow(1.0 - VoH, 5.0);
    mean += w * glm::dvec3(l);
  }
  LtcLobeMoments m;
  m.norm = norm / n;
  m.fresnel = fresnel / n;
  const double len = glm::length(mean);
  m.mean = len > 0.0 ? mean / len : glm::dvec3(0.0, 0.0, 1.0);
  return m;
}

double ltcLobeValue(float roughness, float NoV, double norm, const glm::vec3& l) {
  return lobe(cellAlpha(roughness), cellView(NoV), l) / norm;
}

double ltcFitError(const LtcParams& p, float roughness, float NoV, double norm, int per_dim) {
  return fitError(makeSamples(roughness, NoV, norm, per_dim), p);
}

namespace {

// The cap term of the fit (LtcFitOptions::cap_weight): caps (cones of angular radius kCapRadii)
// centered on directions of the lobe and on the mirror direction, each with the normalized lobe's
// integral over it, which does not depend on the parameters. Only caps entirely above the
// horizon (the lobe is 0 below it; the LTC's sphere integral there is the horizon-clipped
// approximation, not what the fit should match).
struct LobeCap {
  glm::vec3 center;
  float radius = 0.0f;
  double lobe = 0.0;  // integral over the cap of f (n.l) / n_f
};
constexpr float kCapRadii[] = {0.05f, 0.25f, 0.5f};  // radians: 2.9, 14.3 and 28.6 degrees
constexpr int kCapCenters = 24;                      // lobe directions per radius

std::vector<LobeCap> lobeCaps(float roughness, float NoV, double norm, int samples_per_dim) {
  const float alpha = cellAlpha(roughness);
  const glm::vec3 V = cellView(NoV);
  const float nov = std::max(V.z, g::HV_MIN_NOV);
  const float G1 = g::G1_SmithGGX(alpha, nov);
  // The lobe's integral over each cap from GGX visible-normal samples (as integrateLtcLobe).
  const int n = samples_per_dim * samples_per_dim;
  std::vector<glm::vec3> dirs;
  std::vector<double> weights;
  for (int i = 0; i < n; ++i) {
    const glm::vec3 l = glm::reflect(-V, g::sampleGGXVNDF(V, alpha, hammersley2(i, n)));
    if (l.z <= 0.0f) continue;
    dirs.push_back(l);
    weights.push_back(lobeOverVndfPdf(alpha, nov, G1, l.z) / norm / double(n));
  }
  std::vector<LobeCap> caps;
  for (float r : kCapRadii) {
    // Centers: lobe directions from the middle half of the visible normals' second coordinate
    // (the lobe's core and flanks, not its far tail), then the mirror direction.
    for (int k = 0; k <= kCapCenters; ++k) {
      const glm::vec2 u = hammersley2(k, kCapCenters);
      const glm::vec3 H = k == kCapCenters
                              ? glm::vec3(0.0f, 0.0f, 1.0f)
                              : g::sampleGGXVNDF(V, alpha, glm::vec2(u.x, 0.25f + 0.5f * u.y));
      const glm::vec3 c = glm::reflect(-V, H);
      if (c.z <= std::sin(r) + 0.01f) continue;
      LobeCap cap{c, r, 0.0};
      const float cos_r = std::cos(r);
      for (size_t i = 0; i < dirs.size(); ++i) {
        if (glm::dot(dirs[i], c) >= cos_r) cap.lobe += weights[i];
      }
      caps.push_back(cap);
    }
  }
  return caps;
}

// sum over the caps of (integral of D_ltc - the lobe's)^2 / sum of the lobe's integrals^2: the
// relative error of sphere lights of those sizes and places, as ltcSphereIntegral shades them.
double capError(const std::vector<LobeCap>& caps, const LtcParams& p, float alpha,
                const glm::vec3& V) {
  const g::Ltc l = cellLtc(p, alpha, V);
  double e = 0.0, sum = 0.0;
  for (const LobeCap& c : caps) {
    const double I = g::ltcSphereIntegral(l, c.center, std::sin(c.radius));
    e += (I - c.lobe) * (I - c.lobe);
    sum += c.lobe * c.lobe;
  }
  return sum > 0.0 ? e / sum : 0.0;
}

}  // namespace

LtcCell fitLtcCell(float roughness, float NoV, const LtcParams& start, const LtcFitOptions& o) {
  const LtcLobeMoments m = integrateLtcLobe(roughness, NoV, o.moment_samples);
  const float dx = float(m.mean.x);
  const CellSamples s = makeSamples(roughness, NoV, m.norm, o.fit_samples);
  const bool cap_cell =
      NoV <= o.cap_max_nov || (roughness <= o.cap_glossy_roughness && NoV <= o.cap_glossy_nov);
  const std::vector<LobeCap> caps = o.cap_weight > 0.0 && cap_cell
                                        ? lobeCaps(roughness, NoV, m.norm, o.cap_samples)
                                        : std::vector<LobeCap>{};
  const std::array<double, 4> x0 = {std::log(double(std::max(start.ax, 1e-3f))),
                                    std::log(double(std::max(start.ay, 1e-3f))), double(start.sk),
                                    0.0};
  // The pointwise norm relative to its value at the start, so that cap_weight means the same in
  // every cell (the norm's scale grows with the lobe's peak).
  const double e0 =
      caps.empty() ? 1.0 : std::max(fitErrorP(s, toParams(x0, dx), o.error_power), 1e-300);
  auto f = [&](const std::array<double, 4>& x) {
    // Widths outside [1e-3, 1e3] (times alpha) are not lobes; a large value keeps the simplex out.
    if (std::abs(x[0]) > 6.9 || std::abs(x[1]) > 6.9) return 1e30;
    const LtcParams p = toParams(x, dx);
    double e = fitErrorP(s, p, o.error_power) / e0;
    if (!caps.empty()) e += o.cap_weight * capError(caps, p, s.alpha, s.V);
    return e;
  };
  LtcCell c;
  const std::array<double, 4> x = nelderMead(f, x0, o.max_iterations, c.iterations);
  c.params = toParams(x, dx);
  c.norm = m.norm;
  c.fresnel = m.fresnel;
  c.error = fitError(s, c.params);
  return c;
}

double ltcCapError(const LtcParams& p, float roughness, float NoV, double norm,
                   int samples_per_dim) {
  return capError(lobeCaps(roughness, NoV, norm, samples_per_dim), p, cellAlpha(roughness),
                  cellView(NoV));
}

LtcParams ltcFitStart(const LtcTable& t, int i, int j) {
  return i + 1 < t.size ? t.at(i + 1, j).params : LtcParams{};
}

LtcTable fitLtcTable(const LtcFitOptions& o) {
  LtcTable t;
  t.size = o.size;
  t.cells.resize(size_t(o.size) * size_t(o.size));
  std::atomic<int> done{0};
  std::mutex progress_mutex;
  detail::parallelFor(o.size, o.threads, [&](int j) {
    for (int i = o.size - 1; i >= 0; --i) {
      const glm::vec2 rn =
          g::ltcTableParameters(float(i) / float(o.size - 1), float(j) / float(o.size - 1));
      t.cells[size_t(j) * size_t(o.size) + size_t(i)] =
          fitLtcCell(rn.x, rn.y, ltcFitStart(t, i, j), o);
    }
    const int d = ++done;
    if (o.progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      o.progress(d, o.size);
    }
  });
  return t;
}

std::string ltcTableSource(const LtcTable& t, const LtcFitOptions& o, const std::string& command) {
  double worst = 0.0, sum = 0.0;
  for (const LtcCell& c : t.cells) {
    worst = std::max(worst, c.error);
    sum += c.error;
  }
  std::ostringstream s;
  char buf[256];
  s << "// Generated by `" << command << "` (samples/app/cmd_ltc_fit.cpp, engine/eval/src/"
    << "ltc_fit.cpp); do\n// not edit: run the command again. The LTC table of "
       "shaders/common/ltc.glsl, fitted to GGX x\n// height-correlated Smith x cos (F = 1): "
    << t.size << "x" << t.size << " cells, " << o.fit_samples << "^2 + " << o.fit_samples
    << "^2 fit samples, " << o.moment_samples << "^2 moment samples per cell,\n// minimizing "
    << "integral |D_ltc - lobe|^" << o.error_power;
  if (o.cap_weight > 0.0) {
    s << " (relative to the start) + " << o.cap_weight
      << " x the relative squared\n// error of the integrals over caps of the lobe ("
      << o.cap_samples << "^2 lobe samples per cell)";
    if (o.cap_max_nov < 1.0) s << " in the cells of N.V <= " << o.cap_max_nov;
    if (o.cap_glossy_nov > o.cap_max_nov && o.cap_max_nov < 1.0) {
      s << "\n// and of roughness <= " << o.cap_glossy_roughness << ", N.V <= " << o.cap_glossy_nov;
    }
  }
  s << ".\n";
  std::snprintf(buf, sizeof buf,
                "// L1 distance between each cell's LTC and its lobe: mean %.4f, worst %.4f.\n",
                sum / double(t.cells.size()), worst);
  s << buf << "// clang-format off\n#include \"halfvec/shading/ltc_table.hpp\"\n"
    << "#include \"halfvec/shading/shading.hpp\"\n\nnamespace hv {\nnamespace {\n"
    << "// Per cell: a_x/alpha, a_y/alpha, s, tilt, n_f, n_fresnel, fit error, 0.\n"
    << "constexpr float kTable[] = {\n";
  // A float literal that reads back as the same float: 9 significant digits, and a '.' or an
  // exponent before the f suffix.
  auto literal = [](double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.9g", double(float(v)));
    std::string r = b;
    if (r.find_first_of(".en") == std::string::npos) r += ".0";
    return r + "f";
  };
  for (int j = 0; j < t.size; ++j) {
    const float NoV = g::ltcTableParameters(0.0f, float(j) / float(t.size - 1)).y;
    for (int i = 0; i < t.size; ++i) {
      const LtcCell& c = t.at(i, j);
      s << "    " << literal(c.params.ax) << ", " << literal(c.params.ay) << ", "
        << literal(c.params.sk) << ", " << literal(g::ltcTiltFromAxis(c.params.dx, NoV)) << ", "
        << literal(c.norm) << ", " << literal(c.fresnel) << ", " << literal(c.error) << ", 0.0f,\n";
    }
  }
  s << "};\nstatic_assert(sizeof(kTable) / sizeof(float) ==\n"
    << "              HV_LTC_TABLE_SIZE * HV_LTC_TABLE_SIZE * kLtcFloatsPerCell);\n"
    << "}  // namespace\n\nstd::span<const float> ltcTableData() { return kTable; }\n"
    << "std::string_view ltcTableProvenance() {\n  return \"" << command << " (size " << t.size
    << ", fit samples " << o.fit_samples << ", moment samples " << o.moment_samples
    << ", error power " << o.error_power;
  if (o.cap_weight > 0.0) {
    s << ", cap weight " << o.cap_weight << ", cap samples " << o.cap_samples << ", cap max N.V "
      << o.cap_max_nov << ", glossy to roughness " << o.cap_glossy_roughness << " N.V "
      << o.cap_glossy_nov;
  }
  s << ", fit version " << kLtcFitVersion << ")\";\n}\n\n}  // namespace hv\n";
  return s.str();
}

std::string ltcCacheKey(const LtcFitOptions& o) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "halfvec-ltc-fit v%d size %d fit %d moments %d iterations %d power %g caps %g x %d"
                " to N.V %g, glossy to roughness %g N.V %g",
                kLtcFitVersion, o.size, o.fit_samples, o.moment_samples, o.max_iterations,
                o.error_power, o.cap_weight, o.cap_weight > 0.0 ? o.cap_samples : 0,
                o.cap_weight > 0.0 ? o.cap_max_nov : 0.0,
                o.cap_weight > 0.0 ? o.cap_glossy_roughness : 0.0,
                o.cap_weight > 0.0 ? o.cap_glossy_nov : 0.0);
  return buf;
}

std::string ltcCacheBytes(const LtcTable& t, const LtcFitOptions& o) {
  std::string key = ltcCacheKey(o);
  std::string bytes = key + '\n';
  for (const LtcCell& c : t.cells) {
    const double v[8] = {c.params.ax, c.params.ay, c.params.sk, c.params.dx,
                         c.norm,      c.fresnel,   c.error,     double(c.iterations)};
    bytes.append(reinterpret_cast<const char*>(v), sizeof v);
  }
  return bytes;
}

bool loadLtcCache(const std::string& path, const LtcFitOptions& o, LtcTable& t) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::string key;
  if (!std::getline(f, key) || key != ltcCacheKey(o)) return false;
  const size_t n = size_t(o.size) * size_t(o.size);
  std::string rest((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (rest.size() != n * 8 * sizeof(double)) return false;
  t.size = o.size;
  t.cells.resize(n);
  for (size_t k = 0; k < n; ++k) {
    double v[8];
    std::memcpy(v, rest.data() + k * sizeof v, sizeof v);
    LtcCell& c = t.cells[k];
    c.params = {float(v[0]), float(v[1]), float(v[2]), float(v[3])};
    c.norm = v[4];
    c.fresnel = v[5];
    c.error = v[6];
    c.iterations = int(v[7]);
  }
  return true;
}

}  // namespace hv::eval

// `halfvec accuracy`: the accuracy sweep of issue 6. Measures each approximation of the engine
// against the reference and writes docs/accuracy.md (and its heat maps) itself.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "halfvec/eval/engine_aov.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/ibl/ibl_math.hpp"
#include "halfvec/image/metrics.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/eval/light_accuracy.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHelp = R"(Usage: halfvec accuracy [options]

Measures the engine's approximations against the reference (docs/reference.md) and writes the
tables to a markdown file, with heat maps in a folder next to it (<out stem>/*.png):
  - point light: GPU render vs the reference (exact for points);
  - sphere lights: representative point with/without the (alpha/alpha')^2 normalization, both
    sphere-diffuse modes, over roughness x radius/distance x elevation (per shading
    configuration, on the CPU: the engine's formula vs the integral over the emitter);
  - tube lights: eq. 19 vs eq. 18, with/without normalization, over roughness x length x radius;
  - ambient: split sum (table and EnvBRDFApprox) and SH9 vs the reference over roughness, for a
    uniform environment and each .hdr in $HV_ASSETS_DIR/env; EnvBRDFApprox vs the table;
  - the sample scenes: engine vs reference heat maps.

Options:
  --out FILE.md     output (default docs/accuracy.md)
  --quick           small grids and images, few samples (a smoke test; seconds)
  --threads N       CPU threads (default: all cores)
  -h, --help        this text
)";

struct Options {
  std::string out = "docs/accuracy.md";
  bool quick = false;
  int threads = 0;
};

// ---- formatting ----

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string pct(double v) {
  return fmt("%.1f%%", 100.0 * v);
}
std::string spct(double v) {
  return fmt("%+.1f%%", 100.0 * v);
}
std::string num(double v) {
  return fmt("%g", v);
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

std::string row(const std::vector<std::string>& cells) {
  return "| " + join(cells, " | ") + " |\n";
}

std::string headerRow(const std::vector<std::string>& cells) {
  std::string s = row(cells) + "|";
  for (size_t i = 0; i < cells.size(); ++i) s += "---|";
  return s + "\n";
}

// The worst case of one approximation, for the closing summary.
struct Worst {
  std::string name;
  double median = 0.0, worst = 0.0, worst_bias = 0.0;
  std::string where;
  size_t count = 0;
  bool headline = true;  // false: configurations where the reference is a sliver (see text)
};

Worst summarize(const std::string& name, std::vector<std::pair<eval::TermError, std::string>> v) {
  Worst w;
  w.name = name;
  std::vector<double> errs;
  for (auto& [t, where] : v) {
    if (!t.valid) continue;
    errs.push_back(t.rel_error);
    if (t.rel_error >= w.worst) {
      w.worst = t.rel_error;
      w.worst_bias = t.bias;
      w.where = where;
    }
  }
  w.count = errs.size();
  if (!errs.empty()) {
    std::nth_element(errs.begin(), errs.begin() + errs.size() / 2, errs.end());
    w.median = errs[errs.size() / 2];
  }
  return w;
}

// ---- lit-pixel image metrics ----

struct LitStats {
  double rel_error = 0.0, bias = 0.0, noise = 0.0;  // as eval::TermError, over pixels and channels
  // sum of the per-pixel standard errors / sum R: the part of rel_error that noise alone gives
  // (about 0.8 times this for Gaussian noise)
  double pixel_noise = 0.0;
  double ref_sum = 0.0;
  size_t pixels = 0;
};

LitStats litStats(const ImageRGBf& e, const ImageRGBf& r, const ImageRGBf& se,
                  const std::function<bool(size_t)>& use) {
  LitStats s;
  double abs_sum = 0.0, signed_sum = 0.0, var = 0.0, se_sum = 0.0;
  for (size_t i = 0; i < r.px.size(); ++i) {
    if (!use(i)) continue;
    ++s.pixels;
    for (int c = 0; c < 3; ++c) {
      s.ref_sum += r.px[i][c];
      abs_sum += std::abs(double(e.px[i][c]) - r.px[i][c]);
      signed_sum += double(e.px[i][c]) - r.px[i][c];
      var += double(se.px[i][c]) * se.px[i][c];
      se_sum += se.px[i][c];
    }
  }
  if (s.ref_sum > 0.0) {
    s.pixel_noise = se_sum / s.ref_sum;
    s.rel_error = abs_sum / s.ref_sum;
    s.bias = signed_sum / s.ref_sum;
    s.noise = std::sqrt(var) / s.ref_sum;
  }
  return s;
}

// Images restricted to the pixels where `use` holds, packed into one row (for compareImages).
ErrorMetrics compareMasked(const ImageRGBf& e, const ImageRGBf& r,
                           const std::function<bool(size_t)>& use) {
  std::vector<glm::vec3> a, b;
  for (size_t i = 0; i < r.px.size(); ++i) {
    if (!use(i)) continue;
    a.push_back(e.px[i]);
    b.push_back(r.px[i]);
  }
  ImageRGBf ia = makeImageRGBf(int(std::max<size_t>(a.size(), 1)), 1);
  ImageRGBf ib = makeImageRGBf(int(std::max<size_t>(b.size(), 1)), 1);
  for (size_t i = 0; i < a.size(); ++i) {
    ia.px[i] = a[i];
    ib.px[i] = b[i];
  }
  return compareImages(ia, ib);
}

// The shared assets folder, empty when HV_ASSETS_DIR is not set (the sections that need it say
// they were skipped).
std::string assetsDir() {
  const char* e = std::getenv("HV_ASSETS_DIR");
  return e ? e : "";
}

// ---- sections ----

struct Doc {
  std::ostringstream md;
  std::vector<Worst> worst;
};

void pointLightSection(Doc& doc, const Options& opt) {
  Scene s;
  s.camera.position = {0.0f, 2.0f, 3.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  Material m;
  m.base_color = {0.6f, 0.5f, 0.4f};
  m.roughness = 0.35f;
  m.metallic = 0.2f;
  addMeshObject(s, makeSphere(0.8f, 48, 24), m, {0.0f, 0.8f, 0.0f});
  addMeshObject(s, makePlane(6.0f, 6.0f), m, glm::vec3(0.0f));
  for (int k = 0; k < 3; ++k) {
    Light l;
    l.position = {1.5f * float(k - 1), 1.0f + 0.6f * float(k), 1.0f - float(k)};
    l.intensity = 3.0f + float(k);
    l.range = 8.0f;
    s.lights.push_back(l);
  }
  s.environment.kind = EnvironmentKind::None;
  s.settings.falloff_plus_one = false;
  const int w = opt.quick ? 64 : 240, h = opt.quick ? 48 : 180;
  render::Renderer r;
  r.setScene(s);
  const auto aov = eval::renderEngineAovs(r, w, h);
  const auto g = r.readGBuffer();
  ReferenceOptions ro;
  ro.samples = 4;
  ro.threads = opt.threads;
  const ReferenceResult ref = renderReference(s, g, ro);
  auto lit = [&](size_t i) {
    return g.model[i] == static_cast<uint32_t>(ShadingModel::DefaultLit);
  };
  doc.md << "## Point lights\n\n"
         << "Three point lights on a sphere and a floor (" << w << "x" << h
         << ", physical falloff), engine (GPU, RGBA16F target) vs reference. The reference "
            "evaluates point lights in closed form, so its noise is exactly 0 (its reported "
            "standard error: "
         << num(ref.stats.max_rel_error)
         << "); the only expected difference is the engine's half-float target, whose rounding "
            "is 2^-11 = 0.049% relative.\n\n";
  doc.md << headerRow({"term", "lit pixels", "max relative error", "rel. RMSE", "bias"});
  double worst = 0.0;
  for (int k : {0, 1}) {
    const auto which = static_cast<ReferenceAov>(k);
    double max_rel = 0.0;
    for (size_t i = 0; i < g.model.size(); ++i) {
      if (!lit(i)) continue;
      for (int c = 0; c < 3; ++c) {
        const double rv = ref[which].px[i][c];
        if (rv > 1e-3) max_rel = std::max(max_rel, std::abs(aov[k].px[i][c] - rv) / rv);
      }
    }
    worst = std::max(worst, max_rel);
    const ErrorMetrics em = compareMasked(aov[k], ref[which], lit);
    const LitStats ls = litStats(aov[k], ref[which], ref.stdError(which), lit);
    doc.md << row({toString(which), std::to_string(ls.pixels), pct(max_rel), pct(em.rel_rmse),
                   spct(ls.bias)});
  }
  doc.md << "\nMax relative error (pixels with reference > 1e-3): " << pct(worst)
         << ": the point light agrees with the reference to the precision of the half-float "
            "target (tests/reference/test_engine_vs_reference.cpp asserts 0.4% + 1e-5 per "
            "channel).\n\n";
}

void sphereSection(Doc& doc, const Options& opt) {
  eval::SphereSweepGrid g;
  g.threads = opt.threads;
  // radius/distance 1 would put the shading point exactly on the sphere, where the reference's
  // "inside" and "cone" cases meet; 0.98 is the touching case.
  g.radius = {0.01f, 0.05f, 0.1f, 0.25f, 0.5f, 0.98f};
  if (opt.quick) {
    g.roughness = {0.1f, 0.5f};
    g.radius = {0.1f, 0.5f};
    g.elevation_deg = {45.0f, 5.0f};
    g.samples = 256;
  } else {
    g.samples = 4096;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto rows = eval::sweepSphere(g);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto& md = doc.md;
  md << "## Sphere lights\n\n"
     << "Shading point at the origin, N = +z, sphere center at distance 1 and elevation e above "
        "the surface plane (partly below the horizon when e < asin(r)), white light of "
        "intensity 1, physical falloff. Diffuse: white Lambert surface; specular: f0 = 1 "
        "(Fresnel = 1). Per configuration, "
     << "views: the mirror direction of the center, rings of 8 views at 1 and 2 footprints "
        "(2 alpha + angular radius) around it, 8 fixed views. Error over the views: rel. error = "
        "sum|E - R| / sum R, bias = sum(E - R) / sum R (> 0: the engine is too bright), peak = "
        "E/R at the mirror view. Reference: "
     << g.samples << " emitter + " << g.samples
     << " GGX-VNDF samples per view (MIS); its relative standard error is given as noise. "
     << rows.size() << " configurations, " << fmt("%.1f", secs) << " s.\n\n";

  double max_noise_spec = 0.0, max_noise_diff = 0.0;
  for (auto& r : rows) {
    if (r.specular[0].valid) max_noise_spec = std::max(max_noise_spec, r.specular[0].noise);
    if (r.diffuse[0].valid) max_noise_diff = std::max(max_noise_diff, r.diffuse[0].noise);
  }
  md << "Reference noise (relative standard error of the sum over views), worst configuration: "
     << "specular " << pct(max_noise_spec) << ", diffuse " << pct(max_noise_diff) << ".\n\n";

  // Entirely above the horizon: elevation >= the sphere's angular radius asin(r/d).
  auto above = [](const eval::SphereSweepRow& r) {
    return double(r.elevation_deg) >=
           std::asin(std::min(double(r.radius), 1.0)) * 180.0 / 3.14159265358979;
  };
  // Specular: roughness x radius, worst over elevations, per normalization.
  auto worstOverElevation = [&](float rough, float rad, int sn) {
    eval::TermError w;
    for (auto& r : rows) {
      if (r.roughness != rough || r.radius != rad || !r.specular[sn].valid || !above(r)) continue;
      if (!w.valid || r.specular[sn].rel_error > w.rel_error) w = r.specular[sn];
    }
    return w;
  };
  std::vector<std::string> head{"roughness \\ r/d"};
  for (float rad : g.radius) head.push_back(num(rad));
  for (int sn : {1, 0}) {
    md << "### Specular " << (sn ? "with" : "without")
       << " the (alpha/alpha')^2 normalization: rel. error (bias), worst over the elevations "
          "with the sphere entirely above the horizon\n\n";
    md << headerRow(head);
    for (float rough : g.roughness) {
      std::vector<std::string> cells{num(rough)};
      for (float rad : g.radius) {
        const eval::TermError t = worstOverElevation(rough, rad, sn);
        cells.push_back(t.valid ? pct(t.rel_error) + " (" + spct(t.bias) + ")" : "n/a");
      }
      md << row(cells);
    }
    md << "\n";
  }
  // Straddling the horizon: the reference is what little of the sphere is above it.
  md << "### Specular of spheres straddling the horizon (elevation < asin(r/d)): bias with / "
        "without normalization\n\n"
     << "Here the reference only sees the part of the sphere above the horizon, which can be a "
        "sliver, while the representative point still lights the surface, so relative errors "
        "grow without bound as the visible part shrinks (\"no light\": the sphere is entirely "
        "below).\n\n";
  {
    std::vector<std::string> h2{"roughness, elevation \\ r/d"};
    for (float rad : g.radius) h2.push_back(num(rad));
    md << headerRow(h2);
    for (float rough : g.roughness) {
      for (float el : g.elevation_deg) {
        bool any = false;
        std::vector<std::string> cells{num(rough) + ", " + num(el)};
        for (float rad : g.radius) {
          std::string c = "above";
          for (auto& r : rows) {
            if (r.roughness != rough || r.radius != rad || r.elevation_deg != el) continue;
            if (above(r)) break;
            any = true;
            c = r.specular[1].valid ? spct(r.specular[1].bias) + " / " + spct(r.specular[0].bias)
                                    : "no light";
          }
          cells.push_back(c);
        }
        if (any) md << row(cells);
      }
    }
    md << "\n";
  }
  // Where the normalization helps.
  size_t helps = 0, total = 0;
  std::vector<std::string> hurts;
  for (auto& r : rows) {
    if (!r.specular[0].valid) continue;
    ++total;
    if (r.specular[1].rel_error <= r.specular[0].rel_error) {
      ++helps;
    } else {
      hurts.push_back("roughness " + num(r.roughness) + ", r/d " + num(r.radius) + ", e " +
                      num(r.elevation_deg) + ": " + pct(r.specular[1].rel_error) + " vs " +
                      pct(r.specular[0].rel_error));
    }
  }
  md << "The normalization reduces the specular error in " << helps << " of " << total
     << " configurations";
  if (hurts.empty()) {
    md << ".\n\n";
  } else {
    md << "; it increases it in:\n\n";
    const size_t shown = std::min<size_t>(hurts.size(), 12);
    for (size_t i = 0; i < shown; ++i) md << "- " << hurts[i] << "\n";
    if (hurts.size() > shown) md << "- ... and " << hurts.size() - shown << " more\n";
    md << "\n";
  }

  // Bevy #13327: is the (normalized) sphere specular too bright?
  md << "### Is the sphere-light specular too bright? (bevy #13327)\n\n"
     << "Bias and peak ratio E/R of the default (normalized) specular, per elevation; rows "
        "roughness, columns r/d; cell = bias / peak.\n\n";
  for (float el : g.elevation_deg) {
    if (el <= 0.0f) continue;
    md << "Elevation " << num(el) << " degrees:\n\n" << headerRow(head);
    for (float rough : g.roughness) {
      std::vector<std::string> cells{num(rough)};
      for (float rad : g.radius) {
        std::string c = "n/a";
        for (auto& r : rows) {
          if (r.roughness == rough && r.radius == rad && r.elevation_deg == el &&
              r.specular[1].valid) {
            c = spct(r.specular[1].bias) + " / " + fmt("%.2f", r.specular[1].peak);
          }
        }
        cells.push_back(c);
      }
      md << row(cells);
    }
    md << "\n";
  }
  size_t bright = 0, dim = 0, valid = 0;
  double max_bias = -1e30, max_peak = 0.0;
  std::string max_bias_where, max_peak_where;
  for (auto& r : rows) {
    const eval::TermError& t = r.specular[1];
    if (!t.valid || !above(r)) continue;
    ++valid;
    if (t.bias > 0.1) ++bright;
    if (t.bias < -0.1) ++dim;
    const std::string where = "roughness " + num(r.roughness) + ", r/d " + num(r.radius) +
                              ", elevation " + num(r.elevation_deg);
    if (t.bias > max_bias) {
      max_bias = t.bias;
      max_bias_where = where;
    }
    if (t.peak > max_peak) {
      max_peak = t.peak;
      max_peak_where = where;
    }
  }
  md << "**Answer:** yes, where the lobe is narrower than the sphere. Over the " << valid
     << " configurations with the sphere entirely above the horizon, the normalized specular is "
     << "more than 10% too bright (bias > +10%) in " << bright << " and more than 10% too dark in "
     << dim << ". Largest bias " << spct(max_bias) << " (" << max_bias_where
     << "); largest peak ratio " << fmt("%.2f", max_peak) << " (" << max_peak_where << "). ";
  // The two mechanisms, with the measured peak ratios that show them.
  auto peakAt = [&](float rough, float rad, float el) {
    for (auto& r : rows) {
      if (r.roughness == rough && r.radius == rad && r.elevation_deg == el && r.specular[1].valid)
        return r.specular[1].peak;
    }
    return 0.0;
  };
  const float smooth = g.roughness.front(),
              big = g.radius.size() > 1 ? g.radius[g.radius.size() - 2] : g.radius.back();
  const float top = g.elevation_deg.front();
  float low = top;
  for (float el : g.elevation_deg) {
    if (el > 0.0f && el < low) low = el;
  }
  md << "Two causes: (1) for a lobe much narrower than the sphere the exact highlight is the "
        "emitter radiance times the lobe's integral, i.e. D averaged over the sphere's image in "
        "half-vector space, a disc of angular radius about asin(r/d)/2 at normal incidence, while "
        "Karis's alpha' = alpha + r/(3d) widens the lobe by only a third: the peak comes out "
        "(3/2)^2 = 2.25 times too bright (measured peak ratio at roughness "
     << num(smooth) << ", r/d " << num(big) << ", elevation " << num(top) << ": "
     << fmt("%.2f", peakAt(smooth, big, top))
     << "); (2) the half-vector image of the sphere grows as 1/(4 VoH) toward grazing angles and "
        "the normalization ignores VoH, so the excess grows as the light and the view drop "
        "toward the horizon (same configuration at elevation "
     << num(low) << ": " << fmt("%.2f", peakAt(smooth, big, low))
     << "). Later UE4 versions' EnergyNormalization (ShadingModels.ush, New_a2) divides its "
        "widening by VoH, which addresses (2). Rough surfaces (lobe wider than the sphere) are "
        "within a few percent, or slightly too dark for spheres filling much of the "
        "hemisphere.\n\n";

  // Diffuse: Lambert, so independent of roughness and view: radius x elevation.
  md << "### Diffuse (Lambert: independent of roughness): rel. error (bias), KarisPoint / "
        "HorizonCorrect\n\n";
  std::vector<std::string> dhead{"elevation \\ r/d"};
  for (float rad : g.radius) dhead.push_back(num(rad));
  md << headerRow(dhead);
  for (float el : g.elevation_deg) {
    std::vector<std::string> cells{num(el)};
    for (float rad : g.radius) {
      std::string c = "n/a";
      for (auto& r : rows) {
        if (r.roughness == g.roughness.front() && r.radius == rad && r.elevation_deg == el) {
          if (r.diffuse[0].valid) {
            c = pct(r.diffuse[0].rel_error) + " (" + spct(r.diffuse[0].bias) + ") / " +
                pct(r.diffuse[1].rel_error) + " (" + spct(r.diffuse[1].bias) + ")";
          } else {
            c = "no light (engine: " + fmt("%.2g", r.diffuse[0].engine_sum) + " / " +
                fmt("%.2g", r.diffuse[1].engine_sum) + ")";
          }
        }
      }
      cells.push_back(c);
    }
    md << row(cells);
  }
  md << "\n";

  auto where = [](const eval::SphereSweepRow& r) {
    return "sphere, roughness " + num(r.roughness) + ", r/d " + num(r.radius) + ", elevation " +
           num(r.elevation_deg);
  };
  std::vector<std::pair<eval::TermError, std::string>> s1, s0, s1h, s0h, d0, d1;
  for (auto& r : rows) {
    (above(r) ? s1 : s1h).push_back({r.specular[1], where(r)});
    (above(r) ? s0 : s0h).push_back({r.specular[0], where(r)});
    d0.push_back({r.diffuse[0], where(r)});
    d1.push_back({r.diffuse[1], where(r)});
  }
  doc.worst.push_back(summarize(
      "sphere specular, representative point + normalization (default), sphere above the horizon",
      s1));
  doc.worst.push_back(summarize(
      "sphere specular, representative point, no normalization, sphere above the horizon", s0));
  Worst h1 = summarize(
      "sphere specular, representative point + normalization (default), straddling the horizon",
      s1h);
  h1.headline = false;
  doc.worst.push_back(h1);
  doc.worst.push_back(summarize("sphere diffuse, KarisPoint (default)", d0));
  doc.worst.push_back(summarize("sphere diffuse, HorizonCorrect", d1));
}

void tubeSection(Doc& doc, const Options& opt) {
  eval::TubeSweepGrid g;
  g.threads = opt.threads;
  if (opt.quick) {
    g.roughness = {0.2f, 0.6f};
    g.length = {0.5f, 2.0f};
    g.radius = {0.05f};
    g.samples = 256;
  } else {
    g.samples = 4096;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto rows = eval::sweepTube(g);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto& md = doc.md;
  md << "## Tube lights\n\n"
     << "Capsule of length len and radius r, center at distance 1 and elevation "
     << num(g.elevation_deg)
     << " degrees, axis parallel to the surface, once across and once along the plane of "
        "incidence (the views of both orientations are summed into one error); physical "
        "falloff, surfaces and views as for the sphere. Reference: "
     << g.samples << " + " << g.samples << " samples per view. " << rows.size()
     << " configurations, " << fmt("%.1f", secs) << " s.\n\n";
  double max_noise = 0.0;
  for (auto& r : rows) {
    if (r.specular[0][0].valid) max_noise = std::max(max_noise, r.specular[0][0].noise);
    if (r.diffuse.valid) max_noise = std::max(max_noise, r.diffuse.noise);
  }
  md << "Reference noise, worst configuration: " << pct(max_noise) << ".\n\n";
  std::vector<std::string> head{"roughness \\ len, r"};
  for (float len : g.length)
    for (float rad : g.radius) head.push_back(num(len) + ", " + num(rad));
  const char* names[2][2] = {
      {"eq. 19 (closest point), no normalization",
       "eq. 19 (closest point) + normalization (default)"},
      {"eq. 18 (smallest angle), no normalization", "eq. 18 (smallest angle) + normalization"}};
  for (int ts : {0, 1}) {
    for (int tn : {1, 0}) {
      md << "### Specular, " << names[ts][tn] << ": rel. error (bias)\n\n" << headerRow(head);
      for (float rough : g.roughness) {
        std::vector<std::string> cells{num(rough)};
        for (float len : g.length)
          for (float rad : g.radius) {
            std::string c = "n/a";
            for (auto& r : rows) {
              if (r.roughness == rough && r.length == len && r.radius == rad &&
                  r.specular[ts][tn].valid) {
                c = pct(r.specular[ts][tn].rel_error) + " (" + spct(r.specular[ts][tn].bias) + ")";
              }
            }
            cells.push_back(c);
          }
        md << row(cells);
      }
      md << "\n";
    }
  }
  size_t eq18_better = 0, norm_better = 0, total = 0;
  for (auto& r : rows) {
    if (!r.specular[0][1].valid) continue;
    ++total;
    if (r.specular[1][1].rel_error < r.specular[0][1].rel_error) ++eq18_better;
    if (r.specular[0][1].rel_error <= r.specular[0][0].rel_error) ++norm_better;
  }
  md << "Eq. 18 beats eq. 19 (both normalized) in " << eq18_better << " of " << total
     << " configurations; the normalization reduces the eq. 19 error in " << norm_better << " of "
     << total << ".\n\n";
  md << "### Diffuse (Karis eq. 16 vs the capsule): rel. error (bias)\n\n";
  std::vector<std::string> dhead{"len \\ r"};
  for (float rad : g.radius) dhead.push_back(num(rad));
  md << headerRow(dhead);
  for (float len : g.length) {
    std::vector<std::string> cells{num(len)};
    for (float rad : g.radius) {
      std::string c = "n/a";
      for (auto& r : rows) {
        if (r.roughness == g.roughness.front() && r.length == len && r.radius == rad &&
            r.diffuse.valid) {
          c = pct(r.diffuse.rel_error) + " (" + spct(r.diffuse.bias) + ")";
        }
      }
      cells.push_back(c);
    }
    md << row(cells);
  }
  md << "\n";
  auto where = [](const eval::TubeSweepRow& r) {
    return "tube, roughness " + num(r.roughness) + ", len " + num(r.length) + ", r " +
           num(r.radius);
  };
  std::vector<std::pair<eval::TermError, std::string>> v[2][2], d;
  for (auto& r : rows) {
    for (int ts = 0; ts < 2; ++ts)
      for (int tn = 0; tn < 2; ++tn) v[ts][tn].push_back({r.specular[ts][tn], where(r)});
    d.push_back({r.diffuse, where(r)});
  }
  for (int ts = 0; ts < 2; ++ts)
    for (int tn : {1, 0})
      doc.worst.push_back(summarize(std::string("tube specular, ") + names[ts][tn], v[ts][tn]));
  doc.worst.push_back(summarize("tube diffuse, Karis eq. 16", d));
}

// A row of metallic spheres (f0 = 1: ambient specular alone) above a row of white dielectric
// spheres, one roughness per column, seen from the front, lit only by `env`.
Scene ambientScene(const Environment& env, const std::vector<float>& roughness) {
  Scene s;
  s.camera.position = {0.0f, 0.0f, 8.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 30.0f;
  const Mesh sphere = makeSphere(0.4f, 48, 24);
  const int n = int(roughness.size());
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < n; ++i) {
      Material m;
      m.base_color = glm::vec3(1.0f);
      m.metallic = row == 0 ? 1.0f : 0.0f;
      m.roughness = roughness[size_t(i)];
      addMeshObject(s, sphere, m, {float(i) - 0.5f * float(n - 1), row == 0 ? 0.5f : -0.5f, 0.0f});
    }
  }
  s.environment = env;
  s.settings.falloff_plus_one = false;
  return s;
}

void ambientSection(Doc& doc, const Options& opt) {
  auto& md = doc.md;
  const std::vector<float> roughness =
      opt.quick ? std::vector<float>{0.1f, 0.6f}
                : std::vector<float>{0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f};
  const int w = opt.quick ? 96 : 320, h = opt.quick ? 54 : 180;
  const int samples = opt.quick ? 16 : 512;
  struct Env {
    std::string name;
    Environment env;
    std::string skipped;
  };
  std::vector<Env> envs;
  Env uni;
  uni.name = "uniform (radiance 1)";
  uni.env.kind = EnvironmentKind::Uniform;
  uni.env.color = glm::vec3(1.0f);
  envs.push_back(uni);
  const fs::path env_dir = fs::path(assetsDir()) / "env";
  std::vector<fs::path> hdrs;
  std::error_code ec;
  if (fs::is_directory(env_dir, ec)) {
    for (auto& e : fs::directory_iterator(env_dir, ec)) {
      if (e.path().extension() == ".hdr") hdrs.push_back(e.path());
    }
  }
  std::sort(hdrs.begin(), hdrs.end());
  if (hdrs.empty()) {
    Env sk;
    sk.name = "HDR environments";
    sk.skipped = "no .hdr in " + env_dir.string() + " (set HV_ASSETS_DIR)";
    envs.push_back(sk);
  }
  if (opt.quick && !hdrs.empty()) hdrs.resize(1);
  for (auto& p : hdrs) {
    Env e;
    e.name = p.filename().string();
    e.env.kind = EnvironmentKind::HdrFile;
    e.env.path = p.string();
    envs.push_back(e);
  }
  md << "## Ambient (image-based) light\n\n"
     << "A row of metallic spheres (base color 1, so f0 = 1 and no diffuse) above a row of white "
        "dielectric spheres, one roughness per column, lit by the environment alone, "
     << w << "x" << h << ". Engine AOVs (`halfvec render --aov`) vs the reference's (" << samples
     << " samples per pixel: cosine, GGX-VNDF and luminance sampling with MIS against the "
        "full-resolution environment). Per roughness: ambient specular over the metallic sphere's "
        "pixels "
        "(split sum with the 2D table, and with EnvBRDFApprox), ambient diffuse (SH9 "
        "irradiance) over the dielectric sphere's; rel. error = sum|E - R| / sum R over pixels "
        "and channels, bias likewise signed, noise = the reference's relative standard error "
        "of the sum (the floor for the bias) / sum of its per-pixel standard errors over sum R "
        "(the floor for the rel. error, which adds per-pixel noise).\n\n";
  std::vector<std::pair<eval::TermError, std::string>> spec_all, spec_approx_all, diff_all;
  for (auto& e : envs) {
    md << "### " << e.name << "\n\n";
    if (!e.skipped.empty()) {
      md << "skipped: " << e.skipped << "\n\n";
      continue;
    }
    Scene s = ambientScene(e.env, roughness);
    if (opt.quick) {
      s.environment.cube_size = 64;
      s.environment.prefilter_samples = 64;
    }
    render::Renderer r;
    r.setScene(s);
    const auto aov = eval::renderEngineAovs(r, w, h);
    s.settings.env_brdf = EnvBrdf::Analytic;
    const auto aov_approx = eval::renderEngineAovs(r, w, h);
    s.settings.env_brdf = EnvBrdf::Table;
    const auto g = r.readGBuffer();
    ReferenceOptions ro;
    ro.samples = samples;
    ro.threads = opt.threads;
    const ReferenceResult ref = renderReference(s, g, ro);
    md << headerRow({"roughness", "specular (table): rel. error", "bias", "noise",
                     "specular (EnvBRDFApprox): rel. error", "bias", "diffuse (SH9): rel. error",
                     "bias", "noise"});
    auto noise = [](const LitStats& l) { return pct(l.noise) + " / " + pct(l.pixel_noise); };
    const auto AS = ReferenceAov::AmbientSpecular, AD = ReferenceAov::AmbientDiffuse;
    for (float rough : roughness) {
      auto group = [&](bool metal) {
        return [&, metal](size_t i) {
          return g.model[i] == static_cast<uint32_t>(ShadingModel::DefaultLit) &&
                 (g.metallic[i] > 0.5f) == metal && std::abs(g.roughness[i] - rough) < 0.01f;
        };
      };
      const LitStats sp = litStats(aov[size_t(AS)], ref[AS], ref.stdError(AS), group(true));
      const LitStats sa = litStats(aov_approx[size_t(AS)], ref[AS], ref.stdError(AS), group(true));
      const LitStats df = litStats(aov[size_t(AD)], ref[AD], ref.stdError(AD), group(false));
      md << row({num(rough), pct(sp.rel_error), spct(sp.bias), noise(sp), pct(sa.rel_error),
                 spct(sa.bias), pct(df.rel_error), spct(df.bias), noise(df)});
      // Summarized by |bias| over the sphere: rel. error adds the reference's per-pixel noise.
      auto te = [](const LitStats& l) {
        eval::TermError t;
        t.valid = l.ref_sum > 0.0;
        t.rel_error = std::abs(l.bias);
        t.bias = l.bias;
        return t;
      };
      const std::string where = e.name + ", roughness " + num(rough);
      spec_all.push_back({te(sp), where});
      spec_approx_all.push_back({te(sa), where});
      diff_all.push_back({te(df), where});
    }
    md << "\n";
  }
  doc.worst.push_back(
      summarize("ambient specular, split sum (table), |bias| per sphere", spec_all));
  doc.worst.push_back(
      summarize("ambient specular, split sum (EnvBRDFApprox), |bias| per sphere", spec_approx_all));
  doc.worst.push_back(summarize("ambient diffuse, SH9 irradiance, |bias| per sphere", diff_all));

  // EnvBRDFApprox vs the table the engine bakes.
  const int size = opt.quick ? 32 : 128;
  const auto table = integrateEnvBrdf(size, opt.quick ? 128 : 1024, std::max(opt.threads, 1));
  double max_abs[2] = {0, 0}, sum_abs[2] = {0, 0}, max_rel = 0.0;
  std::string where_abs[2], where_rel;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const float NoV = (float(i) + 0.5f) / float(size), rough = (float(j) + 0.5f) / float(size);
      const glm::vec2 t = table[size_t(j) * size_t(size) + size_t(i)];
      const glm::vec2 a = glsl::EnvBRDFApproxScaleBias(rough, NoV);
      const float f0s[2] = {0.04f, 1.0f};
      for (int k = 0; k < 2; ++k) {
        const double tv = f0s[k] * t.x + t.y, av = f0s[k] * a.x + a.y;
        const double d = std::abs(av - tv);
        sum_abs[k] += d;
        if (d > max_abs[k]) {
          max_abs[k] = d;
          where_abs[k] = "NoV " + fmt("%.3f", NoV) + ", roughness " + fmt("%.3f", rough);
        }
        if (k == 1 && tv > 0.0 && d / tv > max_rel) {
          max_rel = d / tv;
          where_rel = "NoV " + fmt("%.3f", NoV) + ", roughness " + fmt("%.3f", rough);
        }
      }
    }
  }
  const double n = double(size) * size;
  md << "### EnvBRDFApprox vs the table\n\n"
     << "Karis 2014's analytic fit against the engine's " << size << "x" << size
     << " table (Karis 2013 eq. 8, integrated as the bake does), at every texel center; the "
        "specular reflectance f0 scale + bias:\n\n"
     << headerRow({"f0", "mean abs. error", "max abs. error", "where"})
     << row({"0.04", fmt("%.4f", sum_abs[0] / n), fmt("%.4f", max_abs[0]), where_abs[0]})
     << row({"1", fmt("%.4f", sum_abs[1] / n), fmt("%.4f", max_abs[1]), where_abs[1]})
     << "\nLargest relative error (f0 = 1): " << pct(max_rel) << " at " << where_rel << ".\n\n";
  Worst wa;
  wa.name = "EnvBRDFApprox vs table (f0 = 1, relative)";
  wa.worst = max_rel;
  wa.median = sum_abs[1] / n;
  wa.where = where_rel;
  wa.count = size_t(n);
  doc.worst.push_back(wa);
}

void sceneSection(Doc& doc, const Options& opt, const fs::path& out_md) {
  auto& md = doc.md;
  const fs::path heat_dir = out_md.parent_path() / out_md.stem();
  fs::create_directories(heat_dir);
  const fs::path scenes = HV_SAMPLES_DIR;
  std::vector<std::string> names =
      opt.quick ? std::vector<std::string>{"default"}
                : std::vector<std::string>{"default", "sphere_grid", "area_lights", "gltf"};
  const int width = opt.quick ? 96 : 320;
  const int samples = opt.quick ? 4 : 128;
  md << "## Sample scenes\n\n"
     << "Each scene of samples/scenes at width " << width
     << " with `settings.falloff_plus_one=false` (the physical falloff the reference integrates), "
        "engine vs reference ("
     << samples
     << " samples per pixel), lit pixels only (emissive excluded). Heat maps: relative error "
        "per pixel (metrics.hpp relativeError), 0 to 50%. `many_lights` is not included: its 1536 "
        "lights make the reference take hours on this machine.\n\n";
  for (const std::string& name : names) {
    const fs::path path = scenes / (name + ".json");
    Scene s = loadScene(path.string(), {"settings.falloff_plus_one=false"});
    const int w = width;
    const int h = std::max(
        1, int(std::lround(double(width) * s.settings.height / std::max(1, s.settings.width))));
    render::Renderer r;
    r.setScene(s);
    const auto aov = eval::renderEngineAovs(r, w, h);
    const auto g = r.readGBuffer();
    ReferenceOptions ro;
    ro.samples = samples;
    ro.threads = opt.threads;
    const ReferenceResult ref = renderReference(s, g, ro);
    ImageRGBf engine = makeImageRGBf(w, h);
    for (const auto& a : aov)
      for (size_t i = 0; i < a.px.size(); ++i) engine.px[i] += a.px[i];
    ImageRGBf refimg = ref.image;
    auto lit = [&](size_t i) {
      return g.model[i] == static_cast<uint32_t>(ShadingModel::DefaultLit);
    };
    for (size_t i = 0; i < refimg.px.size(); ++i) {
      if (!lit(i)) refimg.px[i] = glm::vec3(0.0f);
    }
    const std::string png = name + ".png";
    writePng((heat_dir / png).string(), relativeErrorHeatMap(engine, refimg, 0.5f));
    md << "### " << name << "\n\n"
       << "![relative error, " << name << "](" << out_md.stem().string() << "/" << png << ")\n\n"
       << "Reference: " << ref.stats.lit_pixels << " lit pixels, relative standard error mean "
       << pct(ref.stats.mean_rel_error) << ", max " << pct(ref.stats.max_rel_error) << ".\n\n"
       << headerRow(
              {"term", "rel. error", "bias", "noise (sum / per pixel)", "rel. RMSE", "p99 rel."});
    const ErrorMetrics all = compareMasked(engine, refimg, lit);
    const LitStats ls = litStats(engine, refimg, ref.std_error, lit);
    md << row({"all", pct(ls.rel_error), spct(ls.bias), pct(ls.noise) + " / " + pct(ls.pixel_noise),
               pct(all.rel_rmse), pct(all.p99_rel)});
    for (int k = 0; k < kReferenceAovCount; ++k) {
      const auto which = static_cast<ReferenceAov>(k);
      const LitStats t = litStats(aov[size_t(k)], ref[which], ref.stdError(which), lit);
      if (t.ref_sum <= 0.0) continue;
      const ErrorMetrics em = compareMasked(aov[size_t(k)], ref[which], lit);
      md << row({toString(which), pct(t.rel_error), spct(t.bias),
                 pct(t.noise) + " / " + pct(t.pixel_noise), pct(em.rel_rmse), pct(em.p99_rel)});
    }
    md << "\n";
  }
}

void summarySection(Doc& doc) {
  auto& md = doc.md;
  std::vector<Worst> w = doc.worst;
  std::sort(w.begin(), w.end(), [](const Worst& a, const Worst& b) { return a.worst > b.worst; });
  md << "## Summary\n\n"
     << "Each approximation's median and worst error over its sweep (rel. error as defined "
        "above; EnvBRDFApprox: the largest relative error of the reflectance, and the mean "
        "absolute error in the median column), worst first.\n\n"
     << headerRow({"approximation", "configurations", "median", "worst", "bias at worst", "where"});
  for (auto& x : w) {
    md << row({x.name, std::to_string(x.count),
               x.name.rfind("EnvBRDFApprox", 0) == 0 ? fmt("%.4f", x.median) : pct(x.median),
               pct(x.worst), x.name.rfind("EnvBRDFApprox", 0) == 0 ? "" : spct(x.worst_bias),
               x.where});
  }
  auto isEnvBrdf = [](const Worst& x) { return x.name.rfind("EnvBRDFApprox", 0) == 0; };
  auto isDefault = [](const Worst& x) { return x.name.find("(default)") != std::string::npos; };
  const Worst* top = nullptr;
  const Worst* top_default = nullptr;
  const Worst* med = nullptr;
  for (auto& x : w) {
    if (!x.headline || isEnvBrdf(x) || x.count == 0) continue;
    if (!top || x.worst > top->worst) top = &x;
    if (isDefault(x) && (!top_default || x.worst > top_default->worst)) top_default = &x;
    if (!med || x.median > med->median) med = &x;
  }
  if (top && top_default && med) {
    md << "\n**Worst approximation:** " << top->name << ": " << pct(top->worst) << " error ("
       << spct(top->worst_bias) << " bias) at " << top->where
       << ". **Worst with the default settings:** " << top_default->name << ": "
       << pct(top_default->worst) << " (" << spct(top_default->worst_bias) << ") at "
       << top_default->where << ", median " << pct(top_default->median)
       << ". **Largest typical (median) error:** " << med->name << ", " << pct(med->median)
       << ". Spheres straddling the horizon are listed separately (their reference can be a "
          "sliver of the sphere, so relative errors there are unbounded).\n";
  }
}

Options parseArgs(const Args& args) {
  Options o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (a == "--out") {
      o.out = value();
    } else if (a == "--quick") {
      o.quick = true;
    } else if (a == "--threads") {
      o.threads = std::atoi(value().c_str());
      if (o.threads < 0) throw UsageError{"--threads expects a count >= 0"};
    } else {
      throw UsageError{"unknown argument '" + a + "'"};
    }
  }
  if (o.out.empty()) throw UsageError{"--out needs a file name"};
  return o;
}

}  // namespace

int cmdAccuracy(const Args& args) {
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(kHelp, stdout);
      return 0;
    }
  }
  const Options opt = parseArgs(args);
  const auto t0 = std::chrono::steady_clock::now();
  auto ctx = createHeadlessContext();
  Doc doc;
  const fs::path out = opt.out;
  if (!out.parent_path().empty()) fs::create_directories(out.parent_path());
  auto step = [&](const char* what, auto&& fn) {
    std::fprintf(stderr, "accuracy: %s...\n", what);
    fn();
  };
  step("point lights", [&] { pointLightSection(doc, opt); });
  step("sphere lights", [&] { sphereSection(doc, opt); });
  step("tube lights", [&] { tubeSection(doc, opt); });
  step("ambient", [&] { ambientSection(doc, opt); });
  step("sample scenes", [&] { sceneSection(doc, opt, out); });
  summarySection(doc);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream f(out);
  if (!f) throw std::runtime_error("cannot write " + out.string());
  f << "<!-- Generated by `halfvec accuracy" << (opt.quick ? " --quick" : "")
    << "` (samples/app/cmd_accuracy.cpp); do not edit by hand, run the command again. -->\n\n"
    << "# Accuracy of the engine's approximations\n\n"
    << "Generated by `halfvec accuracy" << (opt.quick ? " --quick" : "") << " --out " << opt.out
    << "` in " << fmt("%.0f", secs) << " s on " << ctx->renderer()
    << ". Every number below is measured against the CPU reference (docs/reference.md): "
       "the engine's own formulas against the exact integral of the same emitter and BRDF, so "
       "the difference is the error of the approximation alone. Tests asserting these findings: "
       "tests/reference/test_accuracy.cpp.\n\n"
    << doc.md.str();
  std::printf("accuracy: wrote %s (%.1f s)\n", out.string().c_str(), secs);
  return 0;
}

}  // namespace hv::app

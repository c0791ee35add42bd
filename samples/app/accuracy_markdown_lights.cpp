// The sphere- and tube-light sections of docs/accuracy.md.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "app/accuracy_markdown.hpp"

namespace hv::app {

namespace {

using eval::SphereSweepRow;
using eval::TermError;
using eval::TubeSweepRow;

std::string relBiasPeak(const TermError& t) {
  return t.valid ? pct(t.rel_error) + " (" + spct(t.bias) + "), " + fmtNum("%.2f", t.peak) : "n/a";
}

const SphereSweepRow* sphereRow(const eval::SphereAccuracy& a, float rough, float rad, float el) {
  for (const SphereSweepRow& r : a.rows) {
    if (r.roughness == rough && r.radius == rad && r.elevation_deg == el) return &r;
  }
  return nullptr;
}

// Roughness x r/d, the worst configuration over the elevations with the sphere above the
// horizon: rel. error (bias), peak.
std::string sphereMethodTable(const eval::SphereAccuracy& a, int method) {
  std::ostringstream md;
  md << "### Specular, " << eval::sphereSpecularMethods()[size_t(method)].name
     << ": rel. error (bias), peak; worst over the elevations with the sphere above the "
        "horizon\n\n";
  std::vector<std::string> head{"roughness \\ r/d"};
  for (float rad : a.grid.radius) head.push_back(num(rad));
  md << headerRow(head);
  for (float rough : a.grid.roughness) {
    std::vector<std::string> cells{num(rough)};
    for (float rad : a.grid.radius) {
      TermError w;
      for (float el : a.grid.elevation_deg) {
        const SphereSweepRow* r = sphereRow(a, rough, rad, el);
        if (!r || !r->above() || !r->specular[size_t(method)].valid) continue;
        if (!w.valid || r->specular[size_t(method)].rel_error > w.rel_error) {
          w = r->specular[size_t(method)];
        }
      }
      cells.push_back(relBiasPeak(w));
    }
    md << row(cells);
  }
  md << "\n";
  return md.str();
}

// Spheres straddling the horizon: bias of the default and of ltc.
std::string sphereStraddlingTable(const eval::SphereAccuracy& a) {
  std::ostringstream md;
  md << "### Specular of spheres straddling the horizon (elevation < asin(r/d)): bias, "
        "representative point (default) / ltc\n\n"
        "Here the reference only sees the part of the sphere above the horizon, which can be a "
        "sliver: the representative point still lights the surface, so its relative errors grow "
        "without bound as the visible part shrinks; `ltc` integrates the part of the sphere's "
        "cone above the surface (cut at the horizon in world space, docs/lights.md, "
        "\"Straddling spheres\") and clips it in cosine space with the sphere-cap approximation "
        "(\"no light\": the sphere is entirely below).\n\n";
  std::vector<std::string> head{"roughness, elevation \\ r/d"};
  for (float rad : a.grid.radius) head.push_back(num(rad));
  md << headerRow(head);
  for (float rough : a.grid.roughness) {
    for (float el : a.grid.elevation_deg) {
      bool any = false;
      std::vector<std::string> cells{num(rough) + ", " + num(el)};
      for (float rad : a.grid.radius) {
        const SphereSweepRow* r = sphereRow(a, rough, rad, el);
        std::string c = "above";
        if (r && !r->above()) {
          any = true;
          const TermError& rp = r->specular[eval::kSphereRp];
          const TermError& ltc = r->specular[eval::kSphereLtc];
          c = rp.valid ? spct(rp.bias) + " / " + spct(ltc.bias) : "no light";
        }
        cells.push_back(c);
      }
      if (any) md << row(cells);
    }
  }
  md << "\n";
  return md.str();
}

std::string sphereNormalizationList(const eval::SphereAccuracy& a) {
  size_t helps = 0, total = 0;
  std::vector<std::string> hurts;
  for (const SphereSweepRow& r : a.rows) {
    const TermError& with = r.specular[eval::kSphereRp];
    const TermError& without = r.specular[eval::kSphereRpPlain];
    if (!without.valid) continue;
    ++total;
    if (with.rel_error <= without.rel_error) {
      ++helps;
    } else {
      hurts.push_back("roughness " + num(r.roughness) + ", r/d " + num(r.radius) + ", e " +
                      num(r.elevation_deg) + ": " + pct(with.rel_error) + " vs " +
                      pct(without.rel_error));
    }
  }
  std::ostringstream md;
  md << "The (alpha/alpha')^2 normalization reduces the representative point's error in " << helps
     << " of " << total << " configurations"
     << (hurts.empty() ? ".\n\n" : "; it increases it in:\n\n");
  const size_t shown = std::min<size_t>(hurts.size(), 12);
  for (size_t i = 0; i < shown; ++i) md << "- " << hurts[i] << "\n";
  if (hurts.size() > shown) md << "- ... and " << hurts.size() - shown << " more\n";
  if (!hurts.empty()) md << "\n";
  return md.str();
}

// Bevy #13327: the representative point's bias and peak per elevation.
std::string sphereBrightnessTables(const eval::SphereAccuracy& a) {
  std::ostringstream md;
  md << "### Is the representative-point sphere specular too bright? (bevy #13327)\n\n"
     << "Bias and peak ratio E/R of the default (normalized) specular, per elevation; rows "
        "roughness, columns r/d; cell = bias / peak. Yes where the lobe is narrower than the "
        "sphere: for a lobe much narrower than the sphere the exact highlight is the emitter "
        "radiance times the lobe's integral, while Karis's alpha' = alpha + r/(3d) widens the "
        "lobe by only a third of the sphere's half-vector image (about (3/2)^2 = 2.25 times too "
        "bright at normal incidence); that image grows as 1/(4 VoH) toward grazing angles and "
        "the normalization ignores VoH, so the excess grows as the light and the view drop "
        "toward the horizon. Later UE4 versions' EnergyNormalization (ShadingModels.ush, New_a2) "
        "divides its widening by VoH, which addresses the second cause.\n\n";
  std::vector<std::string> head{"roughness \\ r/d"};
  for (float rad : a.grid.radius) head.push_back(num(rad));
  for (float el : a.grid.elevation_deg) {
    if (el <= 0.0f) continue;
    md << "Elevation " << num(el) << " degrees:\n\n" << headerRow(head);
    for (float rough : a.grid.roughness) {
      std::vector<std::string> cells{num(rough)};
      for (float rad : a.grid.radius) {
        const SphereSweepRow* r = sphereRow(a, rough, rad, el);
        const TermError* t = r ? &r->specular[eval::kSphereRp] : nullptr;
        cells.push_back(t && t->valid ? spct(t->bias) + " / " + fmtNum("%.2f", t->peak) : "n/a");
      }
      md << row(cells);
    }
    md << "\n";
  }
  return md.str();
}

std::string sphereDiffuseTable(const eval::SphereAccuracy& a) {
  std::ostringstream md;
  md << "### Diffuse (Lambert: independent of roughness): rel. error (bias), karis_point / "
        "horizon_correct\n\n";
  std::vector<std::string> head{"elevation \\ r/d"};
  for (float rad : a.grid.radius) head.push_back(num(rad));
  md << headerRow(head);
  for (float el : a.grid.elevation_deg) {
    std::vector<std::string> cells{num(el)};
    for (float rad : a.grid.radius) {
      const SphereSweepRow* r = sphereRow(a, a.grid.roughness.front(), rad, el);
      std::string c = "n/a";
      if (r) {
        const TermError& k = r->diffuse[eval::kSphereDiffuseKaris];
        const TermError& h = r->diffuse[eval::kSphereDiffuseHorizon];
        c = k.valid ? pct(k.rel_error) + " (" + spct(k.bias) + ") / " + pct(h.rel_error) + " (" +
                          spct(h.bias) + ")"
                    : "no light (engine: " + fmtNum("%.2g", k.engine_sum) + " / " +
                          fmtNum("%.2g", h.engine_sum) + ")";
      }
      cells.push_back(c);
    }
    md << row(cells);
  }
  md << "\n";
  return md.str();
}

const TubeSweepRow* tubeRow(const eval::TubeAccuracy& a, float rough, float len, float rad,
                            bool along) {
  for (const TubeSweepRow& r : a.rows) {
    if (r.roughness == rough && r.length == len && r.radius == rad && r.along == along) return &r;
  }
  return nullptr;
}

// Roughness x (length, radius) of one tube method; `cell` formats a row's error.
std::string tubeTable(const eval::TubeAccuracy& a, const std::string& title,
                      const std::function<std::string(const TubeSweepRow&)>& cell,
                      const std::vector<bool>& orientations) {
  std::ostringstream md;
  md << "### " << title << "\n\n";
  std::vector<std::string> head{"roughness \\ len, r"};
  for (float len : a.grid.length)
    for (float rad : a.grid.radius) head.push_back(num(len) + ", " + num(rad));
  md << headerRow(head);
  for (float rough : a.grid.roughness) {
    std::vector<std::string> cells{num(rough)};
    for (float len : a.grid.length) {
      for (float rad : a.grid.radius) {
        std::string c;
        for (bool along : orientations) {
          const TubeSweepRow* r = tubeRow(a, rough, len, rad, along);
          c += (c.empty() ? "" : " / ") + (r ? cell(*r) : std::string("n/a"));
        }
        cells.push_back(c);
      }
    }
    md << row(cells);
  }
  md << "\n";
  return md.str();
}

std::string tubeDiffuseTable(const eval::TubeAccuracy& a) {
  std::ostringstream md;
  md << "### Diffuse (Lambert): bias, karis_eq16 (default) / ltc, across and along the plane of "
        "incidence\n\n";
  std::vector<std::string> head{"len \\ r"};
  for (float rad : a.grid.radius) {
    head.push_back(num(rad) + " across");
    head.push_back(num(rad) + " along");
  }
  md << headerRow(head);
  for (float len : a.grid.length) {
    std::vector<std::string> cells{num(len)};
    for (float rad : a.grid.radius) {
      for (bool along : {false, true}) {
        const TubeSweepRow* r = tubeRow(a, a.grid.roughness.front(), len, rad, along);
        cells.push_back(r ? spct(r->diffuse[eval::kTubeDiffuseKaris].bias) + " / " +
                                spct(r->diffuse[eval::kTubeDiffuseLtc].bias)
                          : "n/a");
      }
    }
    md << row(cells);
  }
  md << "\n";
  return md.str();
}

}  // namespace

std::string sphereMarkdown(const eval::SphereAccuracy& a) {
  std::ostringstream md;
  double noise_spec = 0.0, noise_diff = 0.0;
  for (const SphereSweepRow& r : a.rows) {
    if (r.specular[0].valid) noise_spec = std::max(noise_spec, r.specular[0].noise);
    if (r.diffuse[0].valid) noise_diff = std::max(noise_diff, r.diffuse[0].noise);
  }
  md << "## Sphere lights\n\n"
     << "Shading point at the origin, N = +z, sphere center at distance 1 and elevation e above "
        "the surface plane (partly below the horizon when e < asin(r)), white light of intensity "
        "1, physical falloff. Diffuse: white Lambert surface; specular: f0 = 1 (Fresnel = 1). Per "
        "configuration, views: the mirror direction of the center, rings of 8 views at 1 and 2 "
        "footprints (2 alpha + angular radius) around it, 8 fixed views. Error over the views: "
        "rel. error = sum|E - R| / sum R, bias = sum(E - R) / sum R (> 0: the engine is too "
        "bright), peak = E/R at the mirror view. Reference: "
     << a.grid.samples << " emitter + " << a.grid.samples
     << " GGX-VNDF samples per view (MIS), with each method's BRDF terms. " << a.rows.size()
     << " configurations, " << fmtNum("%.1f", a.seconds) << " s. Reference noise (relative "
     << "standard error of the sum over views), worst configuration: specular " << pct(noise_spec)
     << ", diffuse " << pct(noise_diff) << ".\n\n";
  for (int m : {eval::kSphereRp, eval::kSphereLtc, eval::kSphereRpSmith, eval::kSphereRpPlain}) {
    md << sphereMethodTable(a, m);
  }
  md << sphereStraddlingTable(a) << sphereNormalizationList(a) << sphereBrightnessTables(a)
     << sphereDiffuseTable(a);
  return md.str();
}

std::string directionalMarkdown(const eval::SphereAccuracy& a) {
  std::ostringstream md;
  double noise_spec = 0.0;
  for (const SphereSweepRow& r : a.rows) {
    if (r.specular[0].valid) noise_spec = std::max(noise_spec, r.specular[0].noise);
  }
  md << "## Directional lights\n\n"
     << "The sphere sweep with the sphere replaced by a directional light whose disk subtends the "
        "same cone: angular radius sigma = asin(r/d), illuminance 1 at normal incidence, centered "
        "at elevation e (docs/lights.md, \"Directional lights\"). The tables' r/d is sin(sigma); "
        "the first column is the sun's (angular diameter "
     << fmtNum("%.4f", kSunAngularDiameter)
     << " rad). The engine shades the disk with the sphere's code, so where r/d is also a column "
        "of the sphere section its errors are the sphere's. Reference: "
     << a.grid.samples << " + " << a.grid.samples << " samples per view. " << a.rows.size()
     << " configurations, " << fmtNum("%.1f", a.seconds)
     << " s. Reference noise, worst configuration: specular " << pct(noise_spec) << ".\n\n";
  for (int m : {eval::kSphereRp, eval::kSphereLtc, eval::kSphereRpPlain}) {
    md << sphereMethodTable(a, m);
  }
  md << sphereStraddlingTable(a) << sphereDiffuseTable(a);
  return md.str();
}

std::string tubeStraddlingMarkdown(const eval::TubeStraddlingAccuracy& a) {
  std::ostringstream md;
  md << "### Specular of capsules straddling the horizon: bias, ltc (representative point), "
        "across / along the plane of incidence\n\n"
        "The tube sweep with the capsule's axis (parallel to the surface) at elevation 5, 0 and "
        "-5 degrees, with the radii whose capsule crosses the surface plane there; the reference "
        "sees only its part above the surface. "
     << fmtNum("%.1f", a.seconds) << " s.\n\n"
     << headerRow({"goal", "configurations within", "worst peak", "worst bias", ""})
     << goalRow("tube `ltc` specular straddling the horizon, within 15% (bias)",
                eval::checkTubeStraddlingGoal(a, eval::kTubeLtc, 0.15), 0.15)
     << goalRow("tube `ltc` specular straddling the horizon, within 10% (bias)",
                eval::checkTubeStraddlingGoal(a, eval::kTubeLtc, 0.10), 0.10)
     << goalRow("tube eq. 19 + normalization (default) straddling, within 15% (bias)",
                eval::checkTubeStraddlingGoal(a, eval::kTubeRp, 0.15), 0.15)
     << "\n";
  for (const eval::TubeAccuracy& e : a.elevations) {
    md << tubeTable(e, "Elevation " + num(e.grid.elevation_deg) + " degrees",
                    [](const TubeSweepRow& r) {
                      return spct(r.specular[eval::kTubeLtc].bias) + " (" +
                             spct(r.specular[eval::kTubeRp].bias) + ")";
                    },
                    {false, true});
  }
  return md.str();
}

std::string tubeMarkdown(const eval::TubeAccuracy& a) {
  std::ostringstream md;
  double max_noise = 0.0;
  for (const TubeSweepRow& r : a.rows) {
    if (r.specular[0].valid) max_noise = std::max(max_noise, r.specular[0].noise);
  }
  md << "## Tube lights\n\n"
     << "Capsule of length len and radius r, center at distance 1 and elevation "
     << num(a.grid.elevation_deg)
     << " degrees, axis parallel to the surface, across (y) or along (x) the plane of incidence; "
        "physical falloff, surfaces and views as for the sphere. Reference: "
     << a.grid.samples << " + " << a.grid.samples << " samples per view. " << a.rows.size()
     << " configurations, " << fmtNum("%.1f", a.seconds)
     << " s. Reference noise, worst configuration: " << pct(max_noise) << ".\n\n";
  for (int m : {eval::kTubeRp, eval::kTubeLtc}) {
    for (bool along : {false, true}) {
      md << tubeTable(
          a,
          "Specular, " + eval::tubeSpecularMethods()[size_t(m)].name + ", " +
              (along ? "along" : "across") + " the plane of incidence: rel. error (bias), peak",
          [m](const TubeSweepRow& r) { return relBiasPeak(r.specular[size_t(m)]); }, {along});
    }
  }
  for (int m :
       {eval::kTubeRpSmith, eval::kTubeRpPlain, eval::kTubeRpEq18, eval::kTubeRpEq18Plain}) {
    md << tubeTable(
        a,
        "Specular, " + eval::tubeSpecularMethods()[size_t(m)].name + ": rel. error across / along",
        [m](const TubeSweepRow& r) { return pct(r.specular[size_t(m)].rel_error); }, {false, true});
  }
  size_t eq18_better = 0, norm_better = 0, total = 0;
  for (const TubeSweepRow& r : a.rows) {
    if (!r.specular[eval::kTubeRp].valid) continue;
    ++total;
    if (r.specular[eval::kTubeRpEq18].rel_error < r.specular[eval::kTubeRp].rel_error)
      ++eq18_better;
    if (r.specular[eval::kTubeRp].rel_error <= r.specular[eval::kTubeRpPlain].rel_error)
      ++norm_better;
  }
  md << "Eq. 18 beats eq. 19 (both normalized) in " << eq18_better << " of " << total
     << " configurations; the normalization reduces the eq. 19 error in " << norm_better << " of "
     << total << ".\n\n"
     << tubeDiffuseTable(a);
  return md.str();
}

}  // namespace hv::app

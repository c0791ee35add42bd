// Screen-space ambient occlusion (settings.ao: gtao) on the GPU, under a uniform environment of
// radiance L with no lights: the open plane is unoccluded, the floor beside a resting sphere has
// the sphere's analytic occlusion 1 - (R / sqrt(x^2 + R^2))^3 (its projected solid angle over pi;
// tests/reference checks the traced reference against the same formula), the specular occlusion
// darkens only near the sphere, the traced specular occlusion darkens a glossy floor where its
// mirror ray meets a box, and scenes without `ao: gtao` contain no AO code and render the same
// bytes whatever the other ao settings say.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "halfvec/reference/reference.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/shading/shading.hpp"
#include "render_fixture.hpp"

using namespace hv;

namespace {

constexpr float kR = 0.5f;  // the resting sphere's radius
constexpr float kL = 1.0f;  // the environment's radiance
constexpr float kAlbedo = 0.5f;

Material floorMaterial(float metallic = 0.0f, float roughness = 1.0f) {
  Material m;
  m.base_color = glm::vec3(kAlbedo);
  m.metallic = metallic;
  m.roughness = roughness;
  return m;
}

// The floor y = 0 (40 x 40 m) under a uniform environment, seen from `eye`; with `sphere`, a sphere
// of radius kR resting on it at the origin.
Scene floorScene(glm::vec3 eye, glm::vec3 target, bool sphere, const Material& floor) {
  Scene s;
  s.camera.position = eye;
  s.camera.target = target;
  const glm::vec3 fwd = glm::normalize(target - eye);
  s.camera.up = std::abs(fwd.y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0, 1, 0);
  s.camera.fov_y_deg = 53.13f;  // 2 atan(1/2): from 5 m up, x and z in [-2.5, 2.5] m
  s.camera.near_plane = 0.05f;
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(kL);
  s.environment.cube_size = 32;
  s.environment.prefilter_samples = 64;
  addMeshObject(s, makePlane(40.0f, 40.0f), floor, glm::vec3(0.0f));
  if (sphere) addMeshObject(s, makeSphere(kR, 96, 48), floorMaterial(), {0.0f, kR, 0.0f});
  return s;
}

struct Frame {
  ImageRGBf hdr;
  GBufferReadback gb;
};

Frame renderFrame(render::Renderer& r, const Scene& s, int size, render::DebugView view) {
  r.setScene(s);
  r.render(size, size, view);
  return {r.readHdr(), r.readGBuffer()};
}

// World position of pixel i of the frame (top-down rows) from its depth.
glm::vec3 worldPosition(const Scene& s, const GBufferReadback& gb, size_t i) {
  const int x = int(i % size_t(gb.width)), y = int(i / size_t(gb.width));
  const glm::vec2 uv((x + 0.5f) / float(gb.width), 1.0f - (y + 0.5f) / float(gb.height));
  return glsl::reconstructWorldPosition(uv, gb.depth[i],
                                        referenceInvViewProj(s.camera, gb.width, gb.height));
}

bool floorPixel(const Scene& s, const GBufferReadback& gb, size_t i) {
  return isLit(ShadingModel(gb.model[i])) && std::abs(worldPosition(s, gb, i).y) < 2e-3f;
}

}  // namespace

// A plane seen from 1.5 m up at grazing angles out to the horizon: GTAO's ambient diffuse equals
// the unoccluded one (ao none) within 2% at every lit pixel, at full and half resolution.
TEST(AoGpu, OpenPlaneIsUnoccluded) {
  testContext();
  render::Renderer r;
  Scene s = floorScene({0.0f, 1.5f, 4.0f}, {0.0f, 0.0f, -2.0f}, false, floorMaterial());
  const int size = 128;
  const Frame open = renderFrame(r, s, size, render::DebugView::AmbientDiffuse);
  s.settings.ao = AmbientOcclusion::Gtao;
  s.settings.ao_specular = AoSpecular::None;
  for (AoResolution res : {AoResolution::Full, AoResolution::Half}) {
    s.settings.ao_resolution = res;
    const Frame ao = renderFrame(r, s, size, render::DebugView::AmbientDiffuse);
    int lit = 0;
    double worst = 0.0;
    for (size_t i = 0; i < ao.hdr.px.size(); ++i) {
      if (!isLit(ShadingModel(open.gb.model[i]))) continue;
      ++lit;
      worst = std::max(worst, std::abs(double(ao.hdr.px[i].y) / open.hdr.px[i].y - 1.0));
    }
    EXPECT_GT(lit, size * size / 3);
    EXPECT_LT(worst, 0.02) << toString(res);
    std::printf("open plane, %s resolution: worst |gtao / none - 1| = %.4f over %d pixels\n",
                std::string(toString(res)).c_str(), worst, lit);
  }
}

// The floor beside a sphere of radius R resting on it, seen from 5 m straight above: ambient
// diffuse L albedo (1 - (R / D)^3), D the distance from the floor point to the sphere's centre,
// where that is above 0.2 L albedo, at each quality and resolution (the goal, within 10%
// everywhere, and what is asserted below: docs/ambient-occlusion.md); ao_radius 2 m holds all but
// (0.5 / 2)^3 = 1.6% of the occlusion.
TEST(AoGpu, RestingSphereFloorMatchesAnalytic) {
  testContext();
  render::Renderer r;
  Scene s = floorScene({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, true, floorMaterial());
  s.settings.ao = AmbientOcclusion::Gtao;
  s.settings.ao_radius = 2.0f;
  const int size = 192;
  for (AoQuality q : {AoQuality::Low, AoQuality::Medium, AoQuality::High}) {
    for (AoResolution res : {AoResolution::Full, AoResolution::Half}) {
      s.settings.ao_quality = q;
      s.settings.ao_resolution = res;
      const Frame f = renderFrame(r, s, size, render::DebugView::AmbientDiffuse);
      int checked = 0, over = 0;
      double worst = 0.0, sum = 0.0, worst_x = 0.0;
      for (size_t i = 0; i < f.hdr.px.size(); ++i) {
        if (!floorPixel(s, f.gb, i)) continue;
        const glm::vec3 X = worldPosition(s, f.gb, i);
        const double D = std::sqrt(double(X.x) * X.x + double(X.z) * X.z + double(kR) * kR);
        const double expected = kL * kAlbedo * (1.0 - std::pow(kR / D, 3.0));
        if (expected < 0.2 * kL * kAlbedo) continue;
        const double err = std::abs(f.hdr.px[i].y / expected - 1.0);
        if (err > worst) worst_x = std::hypot(double(X.x), double(X.z));
        over += err > 0.10;
        worst = std::max(worst, err);
        sum += err;
        ++checked;
      }
      EXPECT_GT(checked, size * size / 2);
      // The goal (every pixel within 10%) is missed in a ring just outside the sphere's outline
      // (x ~ 0.56 m, seen from above), both ways: too dark where a depth buffer's column under
      // the sphere hides sky that the sphere leaves open, too bright where the first step misses
      // the silhouette (docs/ambient-occlusion.md). Asserted: the mean, at most 0.5% of the
      // pixels over 10%, none over 25%.
      EXPECT_LT(sum / std::max(checked, 1), 0.02) << toString(q) << ", " << toString(res);
      EXPECT_LE(over, checked / 200) << toString(q) << ", " << toString(res);
      EXPECT_LT(worst, 0.25) << toString(q) << ", " << toString(res);
      std::printf(
          "resting sphere, %s quality, %s resolution: |engine / analytic - 1| worst %.4f, mean "
          "%.4f over %d floor pixels; worst at x = %.3f m, %d pixels over 10%%\n",
          std::string(toString(q)).c_str(), std::string(toString(res)).c_str(), worst,
          sum / std::max(checked, 1), checked, worst_x, over);
    }
  }
}

// A rough metal floor (roughness 0.8: the lobe's cone, 2 atan(alpha) = 65 degrees, is wider than
// the visibility cone beside the sphere) under the same sphere: the cone-cone specular occlusion
// leaves the specular far from the sphere (the bent normal and R both straight up) and darkens it
// beside the sphere; Lagarde's form too.
TEST(AoGpu, SpecularOcclusionOnlyNearOccluders) {
  testContext();
  render::Renderer r;
  Scene s = floorScene({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, true, floorMaterial(1.0f, 0.8f));
  const int size = 128;
  const Frame open = renderFrame(r, s, size, render::DebugView::AmbientSpecular);
  s.settings.ao = AmbientOcclusion::Gtao;
  s.settings.ao_radius = 2.0f;
  for (AoSpecular so : {AoSpecular::Cone, AoSpecular::Lagarde}) {
    s.settings.ao_specular = so;
    const Frame f = renderFrame(r, s, size, render::DebugView::AmbientSpecular);
    double far_worst = 0.0, near_sum = 0.0;
    int far_n = 0, near_n = 0;
    for (size_t i = 0; i < f.hdr.px.size(); ++i) {
      if (!floorPixel(s, f.gb, i)) continue;
      const glm::vec3 X = worldPosition(s, f.gb, i);
      const double x = std::hypot(double(X.x), double(X.z));
      const double ratio = f.hdr.px[i].y / open.hdr.px[i].y;
      if (x > 2.2) {
        far_worst = std::max(far_worst, std::abs(ratio - 1.0));
        ++far_n;
      } else if (x > 0.55 && x < 0.62) {
        near_sum += ratio;
        ++near_n;
      }
    }
    EXPECT_GT(far_n, 100);
    EXPECT_GT(near_n, 20);
    EXPECT_LT(far_worst, 0.03) << toString(so);
    EXPECT_LT(near_sum / std::max(near_n, 1), 0.9) << toString(so);
    std::printf(
        "specular occlusion %s: far (x > 2.2 m) worst |so - 1| %.4f, beside the sphere "
        "(0.55 < x < 0.62 m) mean %.3f\n",
        std::string(toString(so)).c_str(), far_worst, near_sum / std::max(near_n, 1));
  }
}

// A glossy metal floor (roughness 0.1) in front of a box, seen from 1 m up and 4 m away: where
// the floor's mirror ray hits the box the reference with visibility has almost no ambient
// specular, elsewhere all of it. The traced specular occlusion (ao_specular: traced) follows the
// reference on both; Lagarde's, from the AO alone, barely darkens the mirrored box. Ratios to the
// engine's specular without AO, floor pixels, 128x128, reference 64 samples per pixel.
TEST(AoGpu, TracedSpecularOcclusionFollowsTheMirrorRay) {
  testContext();
  render::Renderer r;
  Scene s = floorScene({0.0f, 1.0f, 4.0f}, {0.0f, 0.3f, 0.0f}, false, floorMaterial(1.0f, 0.1f));
  addMeshObject(s, makeBox({0.6f, 0.6f, 0.3f}), floorMaterial(), {0.0f, 0.6f, 0.0f});
  const int size = 128;
  const Frame open = renderFrame(r, s, size, render::DebugView::AmbientSpecular);
  ReferenceOptions o;
  o.samples = 64;
  o.visibility = true;
  const ReferenceResult ref = renderReference(s, open.gb, o);
  const ImageRGBf& ref_spec = ref.aov[size_t(ReferenceAov::AmbientSpecular)];
  s.settings.ao = AmbientOcclusion::Gtao;
  for (AoSpecular so : {AoSpecular::Traced, AoSpecular::Lagarde}) {
    s.settings.ao_specular = so;
    const Frame f = renderFrame(r, s, size, render::DebugView::AmbientSpecular);
    double hidden_engine = 0.0, hidden_ref = 0.0, shown_worst = 1.0;
    int hidden = 0, shown = 0, shown_dark = 0;
    for (size_t i = 0; i < f.hdr.px.size(); ++i) {
      if (!floorPixel(s, f.gb, i) || open.hdr.px[i].y <= 0.0f) continue;
      const double want = ref_spec.px[i].y / open.hdr.px[i].y;
      const double got = f.hdr.px[i].y / open.hdr.px[i].y;
      if (want < 0.2) {
        hidden_engine += got;
        hidden_ref += want;
        ++hidden;
      } else if (want > 0.9) {
        shown_worst = std::min(shown_worst, got);
        shown_dark += got < 0.9;
        ++shown;
      }
    }
    const double hidden_mean = hidden_engine / std::max(hidden, 1);
    std::printf(
        "%s: mirrored box (%d floor pixels): engine %.3f, reference %.3f of the open specular; "
        "open floor (%d): %d below 0.9, least %.3f\n",
        std::string(toString(so)).c_str(), hidden, hidden_mean, hidden_ref / std::max(hidden, 1),
        shown, shown_dark, shown_worst);
    EXPECT_GT(hidden, 300);
    EXPECT_GT(shown, 1000);
    if (so == AoSpecular::Traced) {
      EXPECT_LT(hidden_mean, 0.2);
      EXPECT_LT(shown_dark, shown / 100);
    } else {
      EXPECT_GT(hidden_mean, 0.5);  // what the test tells apart
    }
  }
}

// Without `ao: gtao` (or without an environment to occlude) the frame has no AO pass and the
// ambient program no AO code; the manifest says why. With it, the two AO programs and their
// reasons, the bent normal among them only for the cone specular occlusion.
TEST(AoGpu, ManifestHasAoCodeOnlyWithGtao) {
  testContext();
  render::Renderer r;
  auto programNamed = [](const render::Manifest& m, const std::string& name) {
    return std::find_if(m.programs.begin(), m.programs.end(),
                        [&](const gl::VariantInfo& v) { return v.name == name; });
  };
  auto ambientDefine = [&](const render::Manifest& m, const std::string& define) {
    const auto it = programNamed(m, "ambient");
    if (it == m.programs.end()) return std::string("no ambient program");
    for (const std::string& reason : it->reasons) {
      if (reason.rfind(define + "=", 0) == 0) return reason;
    }
    return std::string("missing");
  };
  Scene s = floorScene({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, true, floorMaterial());
  s.settings.ao_quality = AoQuality::High;  // changes no code without ao: gtao
  r.setScene(s);
  r.render(32, 32);
  render::Manifest m = r.manifest();
  EXPECT_EQ(programNamed(m, "gtao"), m.programs.end());
  EXPECT_EQ(programNamed(m, "ao denoise"), m.programs.end());
  EXPECT_EQ(ambientDefine(m, "HV_AO").rfind("HV_AO=0: settings.ao = none", 0), 0u)
      << ambientDefine(m, "HV_AO");
  EXPECT_FALSE(r.variantKey().ao);
  EXPECT_EQ(r.variantKey().settings.ao_quality, AoQuality::Medium);

  s.settings.ao = AmbientOcclusion::Gtao;
  r.setScene(s);
  r.render(32, 32);
  m = r.manifest();
  ASSERT_NE(programNamed(m, "gtao"), m.programs.end());
  EXPECT_NE(programNamed(m, "ao denoise"), m.programs.end());
  EXPECT_EQ(ambientDefine(m, "HV_AO"), "HV_AO=1: settings.ao = gtao");
  const auto& gtao = *programNamed(m, "gtao");
  EXPECT_NE(std::find(gtao.reasons.begin(), gtao.reasons.end(),
                      "HV_AO_QUALITY=2: settings.ao_quality = high"),
            gtao.reasons.end());
  // The bent normal only for the cone specular occlusion, its one reader (lagarde by default).
  EXPECT_NE(std::find(gtao.reasons.begin(), gtao.reasons.end(),
                      "HV_AO_BENT_NORMAL=0: settings.ao_specular = lagarde reads no bent normal"),
            gtao.reasons.end());
  s.settings.ao_specular = AoSpecular::Cone;
  r.setScene(s);
  r.render(32, 32);
  m = r.manifest();
  ASSERT_NE(programNamed(m, "ao denoise"), m.programs.end());
  const auto& denoise = *programNamed(m, "ao denoise");
  EXPECT_NE(std::find(denoise.reasons.begin(), denoise.reasons.end(),
                      "HV_AO_BENT_NORMAL=1: settings.ao_specular = cone reads the bent normal"),
            denoise.reasons.end());
  EXPECT_NE(m.key.find("gtao"), std::string::npos) << m.key;

  s.environment.kind = EnvironmentKind::None;  // nothing to occlude
  r.setScene(s);
  r.render(32, 32);
  m = r.manifest();
  EXPECT_EQ(programNamed(m, "gtao"), m.programs.end());
  EXPECT_FALSE(r.variantKey().ao);
  EXPECT_EQ(r.variantKey().settings.ao, AmbientOcclusion::None);
}

// ao settings other than `ao` itself change nothing without `ao: gtao`: the same key and the same
// bytes; with gtao on, the cavity's own specular occlusion is superseded (ao_specular rules).
TEST(AoGpu, WithoutGtaoTheFrameIsTheSame) {
  testContext();
  render::Renderer r;
  Scene s = floorScene({0.0f, 1.5f, 4.0f}, {0.0f, 0.5f, 0.0f}, true, floorMaterial(0.5f, 0.4f));
  const Frame base = renderFrame(r, s, 64, render::DebugView::None);
  const std::string key = r.variantKey().text();
  s.settings.ao_radius = 7.0f;
  s.settings.ao_quality = AoQuality::Low;
  s.settings.ao_resolution = AoResolution::Full;
  s.settings.ao_specular = AoSpecular::Lagarde;
  s.settings.ao_multi_bounce = true;
  const Frame other = renderFrame(r, s, 64, render::DebugView::None);
  EXPECT_EQ(r.variantKey().text(), key);
  ASSERT_EQ(base.hdr.px.size(), other.hdr.px.size());
  EXPECT_TRUE(std::equal(base.hdr.px.begin(), base.hdr.px.end(), other.hdr.px.begin()));
  s.settings.ao = AmbientOcclusion::Gtao;
  s.settings.specular_occlusion = true;
  r.setScene(s);
  EXPECT_FALSE(r.variantKey().settings.specular_occlusion);
}

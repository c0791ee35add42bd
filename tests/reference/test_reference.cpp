// CPU reference renderer: analytic cases (point light, uniform environment, white furnace),
// Monte Carlo error behaviour (within 3 standard errors, 1/sqrt(N), early stop), determinism.
// Every G-buffer is built by hand: no GL context is needed.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "halfvec/reference/reference.hpp"
#include "halfvec/render/frame_data.hpp"
#include "halfvec/shading/brdf.hpp"
#include "halfvec/shading/shading.hpp"

namespace {

namespace g = hv::glsl;
constexpr double kPi = 3.14159265358979323846;

// Camera at (0, 3, 3) looking at the origin: the ray of the center pixel of an odd-sized image
// hits the origin at view distance sqrt(18), so depth = near / sqrt(18) there.
hv::Scene makeScene() {
  hv::Scene s;
  s.camera.position = {0.0f, 3.0f, 3.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.near_plane = 0.05f;
  s.environment.kind = hv::EnvironmentKind::None;
  return s;
}

// A w x h G-buffer of one material on the plane y = 0 (normal +Y) at every pixel: the depth of
// each pixel is that of its ray's intersection with the plane.
hv::GBufferReadback makeGBuffer(const hv::Scene& scene, int w, int h, glm::vec3 base,
                                float metallic, float roughness, float cavity) {
  hv::GBufferReadback gb;
  gb.width = w;
  gb.height = h;
  const size_t n = size_t(w) * size_t(h);
  gb.base_color.assign(n, base);
  gb.metallic.assign(n, metallic);
  gb.roughness.assign(n, roughness);
  gb.cavity.assign(n, cavity);
  gb.normal.assign(n, glm::vec3(0.0f, 1.0f, 0.0f));
  gb.model.assign(n, uint32_t(hv::ShadingModel::DefaultLit));
  gb.depth.assign(n, 0.0f);
  const glm::mat4 view = glm::lookAt(scene.camera.position, scene.camera.target, scene.camera.up);
  const glm::mat4 inv = hv::referenceInvViewProj(scene.camera, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::vec2 uv((x + 0.5f) / float(w), 1.0f - (y + 0.5f) / float(h));
      glm::vec3 far_point = g::reconstructWorldPosition(uv, 1e-3f, inv);
      glm::vec3 dir = glm::normalize(far_point - scene.camera.position);
      float t = -scene.camera.position.y / dir.y;
      glm::vec3 P = scene.camera.position + t * dir;
      float view_z = -(view * glm::vec4(P, 1.0f)).z;
      gb.depth[size_t(y) * size_t(w) + size_t(x)] = scene.camera.near_plane / view_z;
    }
  return gb;
}

hv::ReferenceOptions fastOptions(int samples) {
  hv::ReferenceOptions o;
  o.samples = samples;
  o.threads = 2;
  o.progress = false;
  return o;
}

const glm::vec3 kV = glm::normalize(glm::vec3(0.0f, 3.0f, 3.0f));  // view at the origin
const glm::vec3 kN(0.0f, 1.0f, 0.0f);

TEST(Reference, CameraMatchesEngineFrameBlock) {
  hv::Scene scene = makeScene();
  glm::mat4 a = hv::referenceInvViewProj(scene.camera, 64, 48);
  glm::mat4 b = hv::render::makeFrameBlock(scene, 64, 48).inv_view_proj;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_FLOAT_EQ(a[c][r], b[c][r]);
  // The center pixel reconstructs the origin.
  hv::GBufferReadback gb = makeGBuffer(scene, 1, 1, glm::vec3(1.0f), 0.0f, 0.5f, 1.0f);
  glm::vec3 P = g::reconstructWorldPosition(glm::vec2(0.5f), gb.depth[0], a);
  EXPECT_NEAR(glm::length(P), 0.0f, 1e-5f);
}

// A point light 2 m above a white Lambert surface (cavity 0.5): the light pass's value, exactly,
// with no samples and zero standard error.
TEST(Reference, PointLightIsAnalytic) {
  hv::Scene scene = makeScene();
  hv::Light l;
  l.position = {0.0f, 2.0f, 0.0f};
  l.intensity = 10.0f;
  l.color = {1.0f, 0.5f, 0.25f};
  l.range = 4.0f;
  scene.lights.push_back(l);
  hv::GBufferReadback gb = makeGBuffer(scene, 1, 1, glm::vec3(1.0f), 0.0f, 0.5f, 0.5f);
  hv::ReferenceResult r = hv::renderReference(scene, gb, fastOptions(64));
  const float falloff = (15.0f / 16.0f) * (15.0f / 16.0f) / (4.0f + 1.0f);  // Karis eq. 9
  const glm::vec3 diffuse = l.color * (10.0f * falloff * float(1.0 / kPi) * 0.5f);
  const glm::vec3 got = r[hv::ReferenceAov::DirectDiffuse].px[0];
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], diffuse[k], 1e-5f * diffuse[k]);
  // Specular: D V F NoL of the engine's BRDF (Disney-remapped V for analytic lights).
  g::Surface s = g::makeSurface(kN, glm::vec3(1.0f), 0.0f, 0.5f, 0.5f);
  hv::BrdfConfig cfg = hv::BrdfConfig::fromSettings(scene.settings);
  glm::vec3 L(0.0f, 1.0f, 0.0f), H = glm::normalize(kV + L);
  glm::vec3 spec =
      hv::evalSpecular(cfg, s, glm::dot(kN, kV), 1.0f, glm::dot(kN, H), glm::dot(kV, H)) * l.color *
      (10.0f * falloff * 0.5f);
  const glm::vec3 got_s = r[hv::ReferenceAov::DirectSpecular].px[0];
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got_s[k], spec[k], 1e-4f * spec[k]);
  EXPECT_EQ(r.samples[0], 0);
  EXPECT_EQ(r.std_error.px[0], glm::vec3(0.0f));
  EXPECT_EQ(r.image.px[0], got + got_s);
}

// A sphere light entirely above the horizon: the reference integrates the emitter of
// docs/lights.md (L_e = I / (pi r^2), windowed, d^2 / (d^2 + 1)), whose Lambert diffuse equals
// the point light's I W cos / (d^2 + 1) / pi exactly (Karis's point approximation is exact for a
// uniform sphere above the horizon). Within 3 standard errors.
TEST(Reference, SphereLightAboveHorizonMatchesPointDiffuse) {
  hv::Scene scene = makeScene();
  hv::Light l;
  l.type = hv::LightType::Sphere;
  l.position = {1.0f, 1.5f, -0.5f};
  l.radius = 0.5f;
  l.intensity = 8.0f;
  l.range = 10.0f;
  scene.lights.push_back(l);
  hv::GBufferReadback gb = makeGBuffer(scene, 1, 1, glm::vec3(1.0f), 0.0f, 0.5f, 0.8f);
  hv::ReferenceResult r = hv::renderReference(scene, gb, fastOptions(4096));
  const float d2 = glm::dot(l.position, l.position);
  const float cos_t = l.position.y / std::sqrt(d2);
  const float expected =
      8.0f * g::falloffWindow(d2, 0.1f) / (d2 + 1.0f) * cos_t * float(1.0 / kPi) * 0.8f;
  const float got = r[hv::ReferenceAov::DirectDiffuse].px[0].x;
  const float se = r.stdError(hv::ReferenceAov::DirectDiffuse).px[0].x;
  EXPECT_GT(se, 0.0f);
  EXPECT_LT(se, 0.01f * expected);
  EXPECT_NEAR(got, expected, 3.0f * se);
}

// A small, far sphere (r = 1 cm at 3 m) is the point light of the same intensity, diffuse and
// specular, within noise (3 standard errors) plus 1e-3 relative for the finite size.
TEST(Reference, TinyFarSphereMatchesPointLight) {
  for (float metallic : {0.0f, 1.0f}) {
    hv::Scene scene = makeScene();
    hv::Light p;
    p.position = {0.5f, 3.0f, 0.5f};
    p.intensity = 20.0f;
    p.range = 20.0f;
    scene.lights.push_back(p);
    hv::GBufferReadback gb =
        makeGBuffer(scene, 1, 1, glm::vec3(0.9f, 0.6f, 0.3f), metallic, 0.5f, 1.0f);
    hv::ReferenceResult rp = hv::renderReference(scene, gb, fastOptions(16));
    scene.lights[0].type = hv::LightType::Sphere;
    scene.lights[0].radius = 0.01f;
    hv::ReferenceResult rs = hv::renderReference(scene, gb, fastOptions(1024));
    for (auto aov : {hv::ReferenceAov::DirectDiffuse, hv::ReferenceAov::DirectSpecular})
      for (int k = 0; k < 3; ++k) {
        const float a = rp[aov].px[0][k], b = rs[aov].px[0][k];
        EXPECT_NEAR(b, a, 3.0f * rs.stdError(aov).px[0][k] + 1e-3f * a)
            << hv::toString(aov) << " metallic " << metallic;
      }
  }
}

// A capsule of length -> 0 is the sphere (docs/lights.md: same L_e and power); area sampling of
// the capsule against cone sampling of the sphere, within 3 combined standard errors.
TEST(Reference, ShortTubeMatchesSphere) {
  hv::Scene scene = makeScene();
  hv::Light l;
  l.type = hv::LightType::Sphere;
  l.position = {0.3f, 1.2f, 0.2f};
  l.radius = 0.3f;
  l.intensity = 5.0f;
  l.range = 10.0f;
  scene.lights.push_back(l);
  hv::GBufferReadback gb = makeGBuffer(scene, 1, 1, glm::vec3(0.8f), 0.0f, 0.4f, 1.0f);
  hv::ReferenceResult rs = hv::renderReference(scene, gb, fastOptions(4096));
  scene.lights[0].type = hv::LightType::Tube;
  scene.lights[0].length = 1e-4f;
  scene.lights[0].axis = glm::normalize(glm::vec3(1.0f, 0.2f, 0.3f));
  hv::ReferenceResult rt = hv::renderReference(scene, gb, fastOptions(4096));
  for (auto aov : {hv::ReferenceAov::DirectDiffuse, hv::ReferenceAov::DirectSpecular}) {
    const float a = rs[aov].px[0].x, b = rt[aov].px[0].x;
    const float se = std::hypot(rs.stdError(aov).px[0].x, rt.stdError(aov).px[0].x);
    EXPECT_GT(se, 0.0f);
    EXPECT_NEAR(b, a, 3.0f * se + 1e-3f * a) << hv::toString(aov);
  }
}

hv::Scene uniformEnvScene(glm::vec3 L) {
  hv::Scene scene = makeScene();
  scene.environment.kind = hv::EnvironmentKind::Uniform;
  scene.environment.color = L;
  scene.environment.intensity = 1.0f;
  return scene;
}

// Uniform environment of radiance L on a white Lambert surface: ambient diffuse = L * cavity
// (the specular f0 = 0.04 goes to the other AOV), within 3 standard errors.
TEST(Reference, UniformEnvironmentLambert) {
  const glm::vec3 L(0.7f, 0.5f, 0.3f);
  hv::Scene scene = uniformEnvScene(L);
  hv::GBufferReadback gb = makeGBuffer(scene, 1, 1, glm::vec3(1.0f), 0.0f, 0.6f, 0.6f);
  hv::ReferenceResult r = hv::renderReference(scene, gb, fastOptions(4096));
  const glm::vec3 got = r[hv::ReferenceAov::AmbientDiffuse].px[0];
  const glm::vec3 se = r.stdError(hv::ReferenceAov::AmbientDiffuse).px[0];
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(se[k], 0.0f);
    EXPECT_LT(se[k], 0.01f * L[k]);
    EXPECT_NEAR(got[k], L[k] * 0.6f, 3.0f * se[k]);
  }
  EXPECT_EQ(r.samples[0], 4096);
  EXPECT_EQ(r[hv::ReferenceAov::DirectDiffuse].px[0], glm::vec3(0.0f));
}

// Directional albedo of the specular lobe with F = 1 (the environment's V at alpha, no remap), by
// midpoint quadrature over the hemisphere in (cos theta, phi).
double specularAlbedoQuadrature(float roughness, glm::vec3 V) {
  hv::BrdfConfig cfg;
  g::Surface s = g::makeSurface(kN, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
  const int nu = 600, nphi = 600;
  double sum = 0.0;
  for (int i = 0; i < nu; ++i) {
    double c = (i + 0.5) / nu;
    double sn = std::sqrt(1.0 - c * c);
    for (int j = 0; j < nphi; ++j) {
      double phi = 2.0 * kPi * (j + 0.5) / nphi;
      glm::vec3 L(float(sn * std::cos(phi)), float(c), float(sn * std::sin(phi)));
      glm::vec3 H = glm::normalize(V + L);
      float NoV = glm::dot(kN, V), NoL = float(c), NoH = glm::dot(kN, H), VoH = glm::dot(V, H);
      sum += double(hv::evalD(cfg, s.alpha, NoH) *
                    hv::evalVForAlpha(cfg, s.alpha, NoV, NoL, NoH, VoH)) *
             c;
    }
  }
  return sum * 2.0 * kPi / (double(nu) * nphi);
}

// White furnace: metallic 1, base color 1 (F = 1) in a uniform environment of radiance 1 gives
// the directional albedo of the BRDF (<= 1 for Schlick-GGX V), against a quadrature and the
// ibl module's Hammersley integral (the env BRDF table's scale + bias).
TEST(Reference, WhiteFurnaceDirectionalAlbedo) {
  hv::Scene scene = uniformEnvScene(glm::vec3(1.0f));
  for (float roughness : {0.3f, 0.7f}) {
    hv::GBufferReadback gb = makeGBuffer(scene, 1, 1, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
    hv::ReferenceResult r = hv::renderReference(scene, gb, fastOptions(4096));
    const float got = r[hv::ReferenceAov::AmbientSpecular].px[0].x;
    const float se = r.stdError(hv::ReferenceAov::AmbientSpecular).px[0].x;
    const double quad = specularAlbedoQuadrature(roughness, kV);
    glm::vec2 ab = hv::integrateEnvBrdfAt(glm::dot(kN, kV), roughness, 4096);
    EXPECT_LE(got, 1.0f + 3.0f * se);
    EXPECT_LE(quad, 1.0);
    EXPECT_NEAR(got, quad, 3.0 * se + 2e-3 * quad) << "roughness " << roughness;
    EXPECT_NEAR(ab.x + ab.y, quad, 5e-3 * quad) << "roughness " << roughness;
    EXPECT_EQ(r[hv::ReferenceAov::AmbientDiffuse].px[0], glm::vec3(0.0f));  // metals: no diffuse
  }
}

// A normal facing away from the viewer (N.V = -0.47; normal maps and interpolated normals give
// them) is shaded as its reflection about the plane across V (viewFacingNormal): the white
// furnace then gives the directional albedo at N.V = +0.47, at most 1. Shaded with N as it is
// and N.V clamped to HV_MIN_NOV the BRDF is no reflectance (H lies along N for L near -V, where
// D and the V term peak): the reference read 0.19 here against the albedo's 0.89.
TEST(Reference, WhiteFurnaceWithANormalFacingAway) {
  hv::Scene scene = uniformEnvScene(glm::vec3(1.0f));
  const float roughness = 0.3f;
  hv::GBufferReadback gb = makeGBuffer(scene, 1, 1, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
  gb.normal[0] = glm::normalize(glm::vec3(0.0f, 0.3f, -1.0f));
  const float NoV = glm::dot(gb.normal[0], kV);
  ASSERT_LT(NoV, -0.4f);
  hv::ReferenceResult r = hv::renderReference(scene, gb, fastOptions(4096));
  const float got = r[hv::ReferenceAov::AmbientSpecular].px[0].x;
  const float se = r.stdError(hv::ReferenceAov::AmbientSpecular).px[0].x;
  // The albedo depends on N.V alone (an isotropic lobe): the quadrature's view at N.V = -NoV.
  const glm::vec3 V_mirror(std::sqrt(1.0f - NoV * NoV), -NoV, 0.0f);
  const double quad = specularAlbedoQuadrature(roughness, V_mirror);
  EXPECT_LE(got, 1.0f + 3.0f * se);
  EXPECT_NEAR(got, quad, 3.0 * se + 2e-3 * quad);
  // The reflected normal itself: unit, facing the viewer as much as N faced away.
  const glm::vec3 Nr = g::viewFacingNormal(gb.normal[0], kV);
  EXPECT_NEAR(glm::length(Nr), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(Nr, kV), -NoV, 1e-6f);
  EXPECT_EQ(g::viewFacingNormal(kN, kV), kN);  // a normal facing the viewer is kept
}

// The standard error falls as 1/sqrt(N): 16x the samples, about 1/4 the error (mean over 25
// pixels, each its own random stream).
TEST(Reference, StandardErrorShrinksAsInverseSqrtN) {
  hv::Scene scene = uniformEnvScene(glm::vec3(1.0f));
  hv::GBufferReadback gb = makeGBuffer(scene, 5, 5, glm::vec3(0.8f), 0.0f, 0.4f, 1.0f);
  auto meanSe = [&](int n) {
    hv::ReferenceResult r = hv::renderReference(scene, gb, fastOptions(n));
    double sum = 0.0;
    for (const glm::vec3& e : r.std_error.px) sum += e.y;
    return sum / double(r.std_error.px.size());
  };
  const double se64 = meanSe(64), se1024 = meanSe(1024);
  EXPECT_GT(se64, 0.0);
  EXPECT_NEAR(se64 / se1024, 4.0, 0.6);
}

TEST(Reference, DeterministicForASeedAndAnyThreadCount) {
  hv::Scene scene = uniformEnvScene(glm::vec3(1.0f, 0.8f, 0.6f));
  hv::GBufferReadback gb = makeGBuffer(scene, 6, 4, glm::vec3(0.5f), 0.5f, 0.5f, 0.9f);
  hv::ReferenceOptions a = fastOptions(32);
  a.threads = 1;
  hv::ReferenceOptions b = fastOptions(32);
  b.threads = 2;
  hv::ReferenceResult ra = hv::renderReference(scene, gb, a);
  hv::ReferenceResult rb = hv::renderReference(scene, gb, b);
  EXPECT_EQ(ra.image.px, rb.image.px);
  EXPECT_EQ(ra.std_error.px, rb.std_error.px);
  b.seed = 2;
  hv::ReferenceResult rc = hv::renderReference(scene, gb, b);
  EXPECT_NE(ra.image.px, rc.image.px);
}

// target_rel_error stops a pixel once its relative standard error is below the target.
TEST(Reference, StopsAtTargetRelativeError) {
  hv::Scene scene = uniformEnvScene(glm::vec3(1.0f));
  hv::GBufferReadback gb = makeGBuffer(scene, 3, 3, glm::vec3(0.8f), 0.0f, 0.5f, 1.0f);
  hv::ReferenceOptions o = fastOptions(1 << 16);
  o.target_rel_error = 0.01f;
  hv::ReferenceResult r = hv::renderReference(scene, gb, o);
  EXPECT_EQ(r.stats.lit_pixels, 9u);
  EXPECT_LT(r.stats.max_samples, 1 << 16);
  EXPECT_GE(r.stats.min_samples, o.min_samples);
  EXPECT_LE(r.stats.max_rel_error, 0.01);
  EXPECT_GT(r.stats.mean_rel_error, 0.0);
}

// Background pixels show the environment along the view ray; unlit pixels stay black.
TEST(Reference, BackgroundIsEnvironmentRadiance) {
  hv::Scene scene = makeScene();
  scene.environment.kind = hv::EnvironmentKind::Sky;
  hv::GBufferReadback gb = makeGBuffer(scene, 4, 3, glm::vec3(1.0f), 0.0f, 0.5f, 1.0f);
  gb.model.assign(gb.model.size(), uint32_t(hv::ShadingModel::Background));
  gb.model[5] = uint32_t(hv::ShadingModel::Unlit);
  hv::ReferenceResult r = hv::renderReference(scene, gb, fastOptions(8));
  hv::EnvSource env = hv::makeEnvSource(scene.environment);
  glm::mat4 inv = hv::render::makeFrameBlock(scene, 4, 3).inv_view_proj;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      const size_t i = size_t(y) * 4 + size_t(x);
      if (i == 5) {
        EXPECT_EQ(r.image.px[i], glm::vec3(0.0f));
        continue;
      }
      glm::vec2 uv((x + 0.5f) / 4.0f, 1.0f - (y + 0.5f) / 3.0f);
      glm::vec3 d =
          glm::normalize(g::reconstructWorldPosition(uv, 1e-3f, inv) - scene.camera.position);
      glm::vec3 e = env.radiance(d);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.image.px[i][k], e[k], 1e-5f * e[k]);
    }
  EXPECT_EQ(r.stats.background_pixels, 11u);
  EXPECT_EQ(r.stats.unlit_pixels, 1u);
  EXPECT_EQ(r.stats.lit_pixels, 0u);
}

}  // namespace

namespace {

// Everything at once on a small image (sky, point + sphere + tube lights, options that change the
// ambient specular, progress on): finite, non-negative, stats consistent with the G-buffer.
TEST(Reference, MixedSceneIsFiniteWithConsistentStats) {
  hv::Scene scene = makeScene();
  scene.environment.kind = hv::EnvironmentKind::Sky;
  scene.settings.specular_occlusion = true;
  scene.settings.energy_compensation = true;
  scene.settings.falloff_plus_one = false;
  hv::Light l;
  l.position = {0.0f, 1.0f, 0.0f};
  scene.lights.push_back(l);
  l.type = hv::LightType::Sphere;
  l.position = {1.0f, 0.5f, 0.0f};
  l.radius = 0.2f;
  scene.lights.push_back(l);
  l.type = hv::LightType::Tube;
  l.position = {-1.0f, 0.3f, 0.5f};
  l.length = 1.0f;
  l.radius = 0.05f;
  scene.lights.push_back(l);
  hv::GBufferReadback gb = makeGBuffer(scene, 16, 12, glm::vec3(0.7f), 0.3f, 0.35f, 0.7f);
  for (size_t i = 0; i < 16; ++i) gb.model[i] = uint32_t(hv::ShadingModel::Background);
  hv::ReferenceOptions o = fastOptions(32);
  o.progress = true;
  hv::ReferenceResult r = hv::renderReference(scene, gb, o);
  for (size_t i = 0; i < r.image.px.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(std::isfinite(r.image.px[i][k])) << i;
      ASSERT_GE(r.image.px[i][k], 0.0f) << i;
    }
  EXPECT_EQ(r.stats.background_pixels, 16u);
  EXPECT_EQ(r.stats.lit_pixels, 16u * 12u - 16u);
  EXPECT_EQ(r.stats.total_samples, 32u * r.stats.lit_pixels);
  EXPECT_GT(r.stats.max_rel_error, 0.0);
  EXPECT_LE(r.stats.mean_rel_error, r.stats.max_rel_error);
  EXPECT_THROW(hv::renderReference(scene, hv::GBufferReadback{}, o), std::invalid_argument);
}

}  // namespace

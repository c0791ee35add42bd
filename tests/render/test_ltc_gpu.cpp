// The LTC light modes on the GPU: the light pass with sphere_specular / tube_specular /
// tube_diffuse = ltc reads the LTC table (two textures bound for that pass only) and gives the
// same radiance as the same shared code compiled as C++ with the same defines, which reads the
// committed table with the same bilinear filter.
#include <cmath>

#include "render_fixture.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/shading/light_gpu.hpp"

#undef HV_MATH_GLSL
#undef HV_BRDF_GLSL
#undef HV_LIGHTS_GLSL
#undef HV_SPOT_GLSL
#undef HV_LTC_GLSL
#undef HV_LTC_LIGHTS_GLSL
#undef HV_LTC_INTEGRALS_GLSL
#undef HV_SAMPLING_GLSL
#undef HV_SPHERE_SPECULAR
#undef HV_TUBE_SPECULAR
#undef HV_TUBE_DIFFUSE
#undef HV_LTC_TABLE
#define HV_SPHERE_SPECULAR 1
#define HV_TUBE_SPECULAR 2
#define HV_TUBE_DIFFUSE 1
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
namespace ltc {
using namespace glm;
using hv::GpuLight;  // gpu_records.glsl, declared once outside the variants
using uint = unsigned int;
namespace {
#include "halfvec/shaders/common/math.glsl"
#include "halfvec/shaders/common/brdf.glsl"
#include "halfvec/shaders/common/lights.glsl"
}  // namespace
}  // namespace ltc
#pragma GCC diagnostic pop

using namespace hv;

// Sphere and tube lights over a glossy and a rough plane, LTC modes (default V: Schlick-GGX, so
// the V ratio is exercised too): GPU HDR = CPU at sampled pixels. Tolerance 1% relative + 1e-5:
// the RGBA16F target (2^-11) and the GPU's texture filter, whose bilinear weights a GPU may round
// to 8 bits (the table's parameters then differ by up to 1/512 of a texel step).
TEST(LtcGpu, MatchesSharedCpuCode) {
  testContext();
  for (LightType type : {LightType::Sphere, LightType::Tube}) {
    for (float rough : {0.15f, 0.6f}) {
      Material m;
      m.base_color = {0.8f, 0.6f, 0.4f};
      m.metallic = 0.5f;
      m.roughness = rough;
      Scene s = planeScene(m);
      Light l;
      l.type = type;
      l.position = {0.2f, 0.6f, -0.1f};
      l.intensity = 3.0f;
      l.radius = 0.2f;
      l.length = type == LightType::Tube ? 0.8f : 0.0f;
      l.axis = glm::normalize(glm::vec3(1, 0, 1));
      l.range = 6.0f;
      s.lights.push_back(l);
      s.settings.sphere_specular = SphereSpecular::Ltc;
      s.settings.tube_specular = TubeSpecular::Ltc;
      s.settings.tube_diffuse = TubeDiffuse::Ltc;
      render::Renderer r;
      r.setScene(s);
      const int w = 64, h = 64;
      r.render(w, h);
      const auto g = r.readGBuffer();
      const auto hdr = r.readHdr();
      const auto frame = render::makeFrameBlock(s, w, h);
      const ltc::GpuLight gl = packLight(l);  // ltc::GpuLight is hv::GpuLight
      int checked = 0;
      float worst = 0.0f;
      for (int y = 2; y < h; y += 5) {
        for (int x = 3; x < w; x += 5) {
          const size_t i = size_t(y) * w + x;
          const glm::vec2 uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h);
          const glm::vec3 P = glsl::reconstructWorldPosition(uv, g.depth[i], frame.inv_view_proj);
          const glm::vec3 V = glm::normalize(s.camera.position - P);
          const ltc::Surface surf = ltc::makeSurface(g.normal[i], g.base_color[i], g.metallic[i],
                                                     g.roughness[i], g.cavity[i]);
          const glm::vec3 cpu = ltc::evaluateLight(gl, surf, P, V);
          for (int k = 0; k < 3; ++k) {
            worst = std::max(worst, std::abs(hdr.px[i][k] - cpu[k]) / (cpu[k] + 1e-4f));
            EXPECT_NEAR(hdr.px[i][k], cpu[k], 1e-2f * cpu[k] + 1e-5f)
                << toString(type) << " roughness " << rough << " pixel " << x << "," << y;
          }
          ++checked;
        }
      }
      EXPECT_GT(checked, 100);
      std::printf("%s, roughness %.2f: max relative GPU-CPU difference %.2e\n",
                  std::string(toString(type)).c_str(), rough, worst);
      // The manifest says what the LTC mode does with the scene's V (Schlick-GGX here).
      bool noted = false;
      for (const auto& prog : r.manifest().programs) {
        for (const std::string& why : prog.reasons) {
          if ((why.rfind("HV_SPHERE_SPECULAR=", 0) == 0 ||
               why.rfind("HV_TUBE_SPECULAR=", 0) == 0) &&
              why.find("smith_ggx_correlated") != std::string::npos) {
            noted = true;
          }
        }
      }
      EXPECT_TRUE(noted) << "the manifest should note the LTC lobe's V";
    }
  }
}

// A sphere light and a capsule lying half below a rough plane (`ltc`): the part below the
// surface is cut off in world space (sphereLtcSpecular, ltcTubeSpecular; docs/lights.md,
// "Straddling spheres"). The tiled light pass takes the cut in a loop of its own after the whole
// light (light_shade.comp, HV_SPLIT_LOOP), brute force per pair; both give the shared code's
// radiance (the whole light plus what the cut changes), tolerance as above; so do the pixels
// inside the light, under its axis, where the whole hemisphere emits (ltcCapsuleIntegral: the
// GPU and the CPU read up to 23% apart there before that rule). The cut must matter here: the
// whole light alone is off by more than 10% at some pixels.
TEST(LtcGpu, StraddlingLightsCutAsTheSharedCpuCode) {
  testContext();
  for (LightType type : {LightType::Sphere, LightType::Tube}) {
    for (Culling culling : {Culling::Tiled, Culling::BruteForce}) {
      Scene s = straddlingLightScene(type);
      const Light l = s.lights[0];
      s.settings.sphere_specular = SphereSpecular::Ltc;
      s.settings.tube_specular = TubeSpecular::Ltc;
      s.settings.culling = culling;
      const int w = 64, h = 64;
      const RenderedFrame f = renderFrame(s, w, h);
      const auto& g = f.g;
      const auto& hdr = f.hdr;
      const auto frame = render::makeFrameBlock(s, w, h);
      const ltc::GpuLight gl = packLight(l);
      const std::string what =
          std::string(toString(type)) + (culling == Culling::Tiled ? ", tiled" : ", brute force");
      int checked = 0, straddling = 0, cut_matters = 0;
      for (int y = 1; y < h; y += 3) {
        for (int x = 1; x < w; x += 3) {
          const size_t i = size_t(y) * w + x;
          if (g.depth[i] <= 0.0f) continue;  // background (reversed Z)
          const glm::vec2 uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h);
          const glm::vec3 P = glsl::reconstructWorldPosition(uv, g.depth[i], frame.inv_view_proj);
          const glm::vec3 V = glm::normalize(s.camera.position - P);
          const ltc::Surface surf = ltc::makeSurface(g.normal[i], g.base_color[i], g.metallic[i],
                                                     g.roughness[i], g.cavity[i]);
          const ltc::ShadingPoint sp = ltc::makeShadingPoint(surf, P, V);
          bool straddles = false;
          glm::vec3 cpu, whole;
          if (type == LightType::Sphere) {
            cpu = ltc::evaluateSphereLightAt(gl, surf, sp);
            whole = ltc::evaluateSphereLightWholeAt(gl, surf, sp, straddles);
          } else {
            cpu = ltc::evaluateTubeLightAt(gl, surf, sp);
            whole = ltc::evaluateTubeLightWholeAt(gl, surf, sp, straddles);
          }
          straddling += straddles ? 1 : 0;
          if (std::abs(whole.g - cpu.g) > 0.1f * cpu.g + 1e-4f) ++cut_matters;
          for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(hdr.px[i][k], cpu[k], 1e-2f * cpu[k] + 1e-5f)
                << what << " pixel " << x << "," << y;
          }
          ++checked;
        }
      }
      EXPECT_GT(checked, 200) << what;
      EXPECT_GT(straddling, checked / 2) << what << ": the light should straddle most horizons";
      EXPECT_LT(straddling, checked) << what << ": the floor under the light's axis lies inside it";
      EXPECT_GT(cut_matters, 20) << what << ": the cut should change the radiance by over 10%";
      std::printf("%s: %d pixels, %d straddling, %d changed by the cut over 10%%\n", what.c_str(),
                  checked, straddling, cut_matters);
    }
  }
}

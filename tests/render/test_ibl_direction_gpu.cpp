// The direction the prefiltered radiance is read along (settings.ibl_direction, ibl.glsl
// prefilteredDirection) and the lobe-sampled radiance (settings.ibl_specular: sampled), checked
// against the CPU reference on rough surfaces under the procedural sky, the cases where reading
// along R, or one texel at all, is far off: the engine's ambient specular term alone
// (HV_AMBIENT_TERMS = 2, no lights) against the reference's ambient specular AOV over the GPU's
// own G-buffer, visibility off (the shading integral alone: nothing occludes in either).
#include <cmath>
#include <iostream>

#include "halfvec/reference/reference.hpp"
#include "render_fixture.hpp"

using namespace hv;

namespace {

Material roughMaterial(float roughness, float metallic) {
  Material m;
  m.base_color = glm::vec3(metallic > 0.5f ? 0.9f : 0.5f);
  m.metallic = metallic;
  m.roughness = roughness;
  m.cavity = 1.0f;
  return m;
}

Material roughMetal(float roughness) {
  return roughMaterial(roughness, 1.0f);
}

Scene skyScene(const Material& m, const Mesh& mesh, float distance, float fov_y_deg) {
  Scene s;
  s.camera.position = {0.0f, 0.0f, distance};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = fov_y_deg;
  s.materials.push_back(m);
  s.meshes.push_back(mesh);
  s.meshes.back().material = 0;
  Object o;
  o.meshes = {0};
  s.objects.push_back(o);
  s.environment.kind = EnvironmentKind::Sky;
  // The sun in the prefiltered cube, as an HDR's sun is: the lookups are what these tests measure
  // (with sky_sun: light the sun is a directional light, docs/ibl.md).
  s.settings.sky_sun = SkySun::Environment;
  s.settings.v = VisibilityTerm::SmithGGXCorrelated;  // the exact V (Heitz 2014)
  s.settings.ambient_terms = 2;                       // ambient specular only
  return s;
}

// Sums of the luminance of engine and reference over the lit pixels a predicate keeps.
struct Sums {
  double engine = 0.0, reference = 0.0;
  int pixels = 0;
  double bias() const { return engine / reference - 1.0; }
};

float luminance(glm::vec3 c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// Engine / reference - 1 of the ambient specular over the lit pixels in `regions` (by N.V and the
// pixel's row), rendered with `direction` and `specular`. The reference is computed once per scene.
template <class Region>
std::vector<Sums> biasByRegion(Scene s, IblDirection direction, const ImageRGBf* reference,
                               int regions, Region region, ImageRGBf* reference_out = nullptr,
                               IblSpecular specular = IblSpecular::SplitSum) {
  s.settings.ibl_direction = direction;
  s.settings.ibl_specular = specular;
  render::Renderer r;
  r.setScene(s);
  constexpr int kSize = 96;
  r.render(kSize, kSize);
  const ImageRGBf engine = r.readHdr();
  const GBufferReadback g = r.readGBuffer();
  ImageRGBf computed;
  if (!reference) {
    ReferenceOptions o;
    o.samples = 64;
    o.visibility = false;
    computed = renderReference(s, g, o).aov[int(ReferenceAov::AmbientSpecular)];
    reference = &computed;
    if (reference_out) *reference_out = computed;
  }
  std::vector<Sums> sums(static_cast<size_t>(regions));
  const glm::vec3 cam = s.camera.position;
  for (size_t i = 0; i < engine.px.size(); ++i) {
    if (g.model[i] != uint32_t(ShadingModel::DefaultLit)) continue;
    const glm::vec3 n = glm::normalize(g.normal[i]);
    const int y = int(i) / kSize;
    const int k = region(n, cam, y, kSize);
    if (k < 0) continue;
    sums[size_t(k)].engine += luminance(engine.px[i]);
    sums[size_t(k)].reference += luminance(reference->px[i]);
    ++sums[size_t(k)].pixels;
  }
  return sums;
}

}  // namespace

// A unit sphere of rough metal (roughness 1) at the origin: N.V of a pixel from its normal (the
// sphere's position is its normal). Grazing: 0.05 <= N.V < 0.3 (the outermost ring, where a pixel
// mixes with the background, left out); facing: N.V >= 0.3.
TEST(IblDirectionGpu, RoughSphereMatchesReference) {
  testContext();
  const Scene s = skyScene(roughMetal(1.0f), makeSphere(1.0f, 96, 48), 4.0f, 32.0f);
  auto region = [](glm::vec3 n, glm::vec3 cam, int, int) {
    const float NoV = glm::dot(n, glm::normalize(cam - n));
    if (NoV < 0.05f) return -1;
    return NoV < 0.3f ? 0 : 1;
  };
  ImageRGBf ref;
  const auto dominant = biasByRegion(s, IblDirection::Dominant, nullptr, 2, region, &ref);
  const auto reflect = biasByRegion(s, IblDirection::Reflect, &ref, 2, region);
  const char* names[] = {"grazing", "facing"};
  for (int k = 0; k < 2; ++k) {
    std::cout << "[ ibl ] roughness 1 sphere, " << names[k] << " (" << dominant[k].pixels
              << " px): engine/reference - 1 = " << dominant[k].bias() << " dominant, "
              << reflect[k].bias() << " reflect\n";
    ASSERT_GT(dominant[k].pixels, 300);
    // 8%: the split sum's own error, which remains along the dominant direction (measured +4.5%
    // facing and +6.4% grazing with these settings, docs/ibl.md), with room for the reference's
    // noise over these sums (below 0.5% at 64 samples per pixel).
    EXPECT_LT(std::abs(dominant[k].bias()), 0.08) << names[k];
  }
  // Read along R the same sphere is far darker than the reference (measured -64% and -34%: the
  // bias this fixes), so the comparison above tells the two directions apart.
  EXPECT_LT(reflect[0].bias(), -0.3);
  EXPECT_LT(reflect[1].bias(), -0.2);
}

// A rough metal plane facing the camera (the glTF-Asset-Generator material planes), seen from close
// with a wide field of view so that R of its lower half points well below the horizon: read along
// R, the lower half reflects the ground and renders much darker than the reference.
TEST(IblDirectionGpu, RoughPlaneLowerHalfMatchesReference) {
  testContext();
  Mesh plane = makePlane(2.4f, 2.4f);  // in y = 0, normal +Y
  for (Vertex& v : plane.vertices) {   // stood up to face the camera (+Z)
    v.position = glm::vec3(v.position.x, -v.position.z, v.position.y);
    v.normal = glm::vec3(0.0f, 0.0f, 1.0f);
    v.tangent = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
  }
  const Scene s = skyScene(roughMetal(1.0f), plane, 1.0f, 90.0f);
  auto region = [](glm::vec3, glm::vec3, int y, int size) { return y >= size / 2 ? 0 : 1; };
  ImageRGBf ref;
  const auto dominant = biasByRegion(s, IblDirection::Dominant, nullptr, 2, region, &ref);
  const auto reflect = biasByRegion(s, IblDirection::Reflect, &ref, 2, region);
  // Rows of the readback go from the top of the image down.
  const char* names[] = {"lower half", "upper half"};
  for (int k = 0; k < 2; ++k) {
    std::cout << "[ ibl ] roughness 1 plane, " << names[k] << " (" << dominant[k].pixels
              << " px): engine/reference - 1 = " << dominant[k].bias() << " dominant, "
              << reflect[k].bias() << " reflect\n";
    ASSERT_GT(dominant[k].pixels, 2000);
    // As for the sphere (measured +4.8% in both halves).
    EXPECT_LT(std::abs(dominant[k].bias()), 0.08) << names[k];
  }
  EXPECT_LT(reflect[0].bias(), -0.25);  // measured -38% (and +14% in the upper half)
}

// The lobe-sampled radiance (ibl_specular: sampled) on the rough spheres where the split sum's one
// texel is furthest off at grazing angles under this sky (roughness 0.75 and 0.5 metal, too dark;
// roughness 1 dielectric, too bright; measured -30%, -27% and +37%): at grazing angles sampled is
// within 6% on the metals and less than 0.4 of the split sum's error on each sphere; facing, where
// the split sum is kept (iblSampledWeight), no worse than it.
TEST(IblSampledGpu, RoughSpheresAtGrazingAnglesMatchReference) {
  testContext();
  auto region = [](glm::vec3 n, glm::vec3 cam, int, int) {
    const float NoV = glm::dot(n, glm::normalize(cam - n));
    if (NoV < 0.05f) return -1;
    return NoV < 0.3f ? 0 : 1;
  };
  const struct { float roughness, metallic; } cases[] = {{0.75f, 1.0f}, {1.0f, 0.0f}, {0.5f, 1.0f}};
  const char* names[] = {"grazing", "facing"};
  for (const auto& c : cases) {
    const Scene s =
        skyScene(roughMaterial(c.roughness, c.metallic), makeSphere(1.0f, 96, 48), 4.0f, 32.0f);
    ImageRGBf ref;
    const auto split = biasByRegion(s, IblDirection::Dominant, nullptr, 2, region, &ref);
    const auto sampled =
        biasByRegion(s, IblDirection::Dominant, &ref, 2, region, nullptr, IblSpecular::Sampled);
    for (int k = 0; k < 2; ++k) {
      std::cout << "[ ibl ] roughness " << c.roughness << " metallic " << c.metallic << " sphere, "
                << names[k] << " (" << sampled[k].pixels
                << " px): engine/reference - 1 = " << split[k].bias() << " split sum, "
                << sampled[k].bias() << " sampled\n";
      ASSERT_GT(sampled[k].pixels, 300);
    }
    const std::string what =
        "roughness " + std::to_string(c.roughness) + " metallic " + std::to_string(c.metallic);
    // Grazing (measured -0.8%, +11.9% and -4.9%).
    EXPECT_GT(std::abs(split[0].bias()), 0.2) << what;
    EXPECT_LT(std::abs(sampled[0].bias()), 0.4 * std::abs(split[0].bias())) << what;
    if (c.metallic > 0.5f) {
      EXPECT_LT(std::abs(sampled[0].bias()), 0.06) << what;
    }
    // Facing: the split sum's own error, unchanged within half a point.
    EXPECT_LT(std::abs(sampled[1].bias()), std::abs(split[1].bias()) + 0.005) << what;
  }
}

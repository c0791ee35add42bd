// Scene-driven specialization on the GPU (docs/variants.md): the programs a frame compiles, read
// back from the manifest and preprocessed by glslangValidator, contain only the code the scene
// needs; the specialized frame matches the uber build; the binary cache round-trips or says
// the driver cannot.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "halfvec/gl/log.hpp"
#include "render_fixture.hpp"

using namespace hv;

namespace {

namespace fs = std::filesystem;

// A small RGBA8 image: checker of two colors (alpha too).
ImageData checker(const std::string& name, glm::u8vec4 a, glm::u8vec4 b) {
  ImageData img;
  img.name = name;
  img.width = img.height = 8;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const glm::u8vec4 c = ((x / 2 + y / 2) % 2) ? a : b;
      img.rgba.insert(img.rgba.end(), {c.r, c.g, c.b, c.a});
    }
  }
  return img;
}

TextureRef ref(int image, int texcoord = 0, float scale = 1.0f) {
  TextureRef t;
  t.image = image;
  t.texcoord = texcoord;
  t.scale = scale;
  return t;
}

// Floor with base color, normal and occlusion (uv1) maps; an emissive sphere with an emissive
// map; an unlit box; a double-sided alpha-masked card. Point and sphere lights, no tube.
Scene featureScene() {
  Scene s;
  s.camera.position = {0.0f, 2.5f, 4.0f};
  s.camera.target = {0.0f, 0.3f, 0.0f};
  s.camera.fov_y_deg = 55.0f;
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(0.3f, 0.35f, 0.4f);
  s.environment.cube_size = 16;
  s.environment.prefilter_samples = 16;
  s.images.push_back(checker("albedo", {200, 180, 160, 255}, {90, 120, 60, 255}));
  s.images.push_back(checker("normal", {128, 128, 255, 255}, {170, 100, 230, 255}));
  s.images.push_back(checker("ao", {255, 255, 255, 255}, {60, 60, 60, 255}));
  s.images.push_back(checker("mask", {255, 255, 255, 255}, {255, 255, 255, 0}));

  Material floor;
  floor.name = "floor";
  floor.roughness = 0.4f;
  floor.base_color = glm::vec3(1.0f);
  floor.base_color_tex = ref(0);
  floor.normal_tex = ref(1);
  floor.occlusion_tex = ref(2, 1, 0.8f);
  Material glow;
  glow.name = "glow";
  glow.base_color = {0.2f, 0.3f, 0.9f};
  glow.metallic = 1.0f;
  glow.roughness = 0.3f;
  glow.emissive = {2.0f, 1.0f, 0.5f};
  glow.emissive_tex = ref(0);
  Material flat;
  flat.name = "flat";
  flat.model = ShadingModel::Unlit;
  flat.base_color = {0.9f, 0.1f, 0.1f};
  Material card;
  card.name = "card";
  card.double_sided = true;
  card.alpha_mode = AlphaMode::Mask;
  card.base_color_tex = ref(3);
  s.materials = {floor, glow, flat, card};

  auto add = [&](Mesh m, int material, glm::mat4 t) {
    m.material = material;
    s.meshes.push_back(std::move(m));
    Object o;
    o.transform = t;
    o.meshes = {int(s.meshes.size() - 1)};
    s.objects.push_back(o);
  };
  Mesh plane = makePlane(6.0f, 6.0f);
  for (auto& v : plane.vertices) v.uv1 = v.uv0 * 2.0f;
  add(plane, 0, glm::mat4(1.0f));
  add(makeSphere(0.5f, 24, 12), 1, glm::translate(glm::mat4(1.0f), {-0.8f, 0.5f, 0.0f}));
  add(makeBox({0.3f, 0.3f, 0.3f}), 2, glm::translate(glm::mat4(1.0f), {0.9f, 0.3f, 0.4f}));
  add(makePlane(1.0f, 1.0f), 3,
      glm::rotate(glm::translate(glm::mat4(1.0f), {0.2f, 0.6f, -0.8f}), 1.2f, {1.0f, 0.0f, 0.0f}));

  Light p;
  p.type = LightType::Point;
  p.position = {0.5f, 1.5f, 1.0f};
  p.intensity = 8.0f;
  p.range = 8.0f;
  Light sp;
  sp.type = LightType::Sphere;
  sp.position = {-1.5f, 1.2f, -0.5f};
  sp.radius = 0.2f;
  sp.color = {1.0f, 0.8f, 0.6f};
  sp.intensity = 6.0f;
  sp.range = 8.0f;
  s.lights = {p, sp};
  return s;
}

// The manifest entry of the last frame named `name` (prefix match).
// The program called `name`, else the first whose name starts with `name` ("gbuffer ...").
const gl::VariantInfo* findProgram(const render::Manifest& m, const std::string& name) {
  for (const auto& p : m.programs) {
    if (p.name == name) return &p;
  }
  for (const auto& p : m.programs) {
    if (p.name.rfind(name, 0) == 0) return &p;
  }
  return nullptr;
}

gl::DefineSet parseDefines(const std::string& key) {
  gl::DefineSet d;
  std::stringstream ss(key);
  std::string item;
  while (std::getline(ss, item, ';')) {
    const auto eq = item.find('=');
    if (eq != std::string::npos) d.push_back({item.substr(0, eq), item.substr(eq + 1)});
  }
  return d;
}

// The program's stage source as the compiler sees it: expanded by the engine (the exact text
// the cache compiles) and preprocessed by glslangValidator -E.
std::string preprocessed(const std::string& stage_path, const gl::DefineSet& defines) {
  const auto src = gl::expandShader(gl::shaderRoot() / stage_path, defines);
  const fs::path dir = fs::temp_directory_path() / "hv_test_variants";
  fs::create_directories(dir);
  const fs::path file = dir / ("src" + fs::path(stage_path).extension().string());
  std::ofstream(file) << src.text;
  const std::string cmd = std::string(HV_GLSLANG_VALIDATOR) + " -E " + file.string() + " 2>&1";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return "popen failed";
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  pclose(p);
  return out;
}

bool has(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

}  // namespace

TEST(Variants, SceneWithoutTubesCompilesNoTubeCode) {
  testContext();
  Scene s = featureScene();
  render::Renderer r;
  r.setScene(s);
  r.render(64, 64);
  const render::Manifest m = r.manifest();
  const gl::VariantInfo* light = findProgram(m, "light");
  ASSERT_NE(light, nullptr);
  ASSERT_EQ(light->stages.size(), 1u);
  const std::string spec = preprocessed(light->stages[0], parseDefines(light->defines));
  ASSERT_TRUE(has(spec, "void main")) << spec.substr(0, 2000);
  EXPECT_TRUE(has(spec, "evaluatePointLight"));
  EXPECT_TRUE(has(spec, "evaluateSphereLight"));
  EXPECT_FALSE(has(spec, "evaluateTubeLight"));
  EXPECT_FALSE(has(spec, "HV_LIGHT_TUBE"));  // not even the dispatch branch

  // The uber build of the same scene has the tube code.
  Scene u = s;
  u.settings.uber = true;
  render::Renderer ru;
  ru.setScene(u);
  ru.render(64, 64);
  const render::Manifest mu = ru.manifest();
  const gl::VariantInfo* light_u = findProgram(mu, "light");
  ASSERT_NE(light_u, nullptr);
  const std::string uber = preprocessed(light_u->stages[0], parseDefines(light_u->defines));
  EXPECT_TRUE(has(uber, "evaluateTubeLight"));
}

TEST(Variants, GBufferProgramsHoldOnlyTheirMaterialsFeatures) {
  testContext();
  Scene s = featureScene();
  render::Renderer r;
  r.setScene(s);
  r.render(64, 64);
  // floor, glow, card have distinct feature sets; flat has none. Four programs.
  ASSERT_EQ(r.gbufferPrograms().size(), 4u);
  const render::Manifest m = r.manifest();
  size_t gbuffer_programs = 0;
  for (const auto& p : m.programs) gbuffer_programs += p.name.rfind("gbuffer", 0) == 0;
  EXPECT_EQ(gbuffer_programs, 4u);
  const auto& key = r.variantKey();
  const auto frag = [&](int material) {
    const auto& d = r.gbufferPrograms().at(size_t(key.material_variant[size_t(material)]));
    return preprocessed("passes/gbuffer.frag", d.defines);
  };
  const std::string flat = frag(2), floor = frag(0), card = frag(3), glow = frag(1);
  ASSERT_TRUE(has(flat, "void main"));
  for (const char* absent : {"t_normal,", "t_occlusion,", "discard", "gl_FrontFacing",
                             "t_emissive,", "v_uv1", "flags.x"}) {
    EXPECT_FALSE(has(flat, absent)) << absent;
  }
  EXPECT_TRUE(has(floor, "texture(t_normal,"));
  EXPECT_TRUE(has(floor, "texture(t_occlusion,"));
  EXPECT_TRUE(has(floor, "v_uv1"));  // the occlusion map reads uv1
  EXPECT_FALSE(has(floor, "discard"));
  EXPECT_TRUE(has(card, "discard"));
  EXPECT_TRUE(has(card, "gl_FrontFacing"));
  EXPECT_FALSE(has(card, "texture(t_normal,"));
  EXPECT_TRUE(has(glow, "texture(t_emissive,"));
  EXPECT_FALSE(has(glow, "texture(t_base_color,"));
}

TEST(Variants, NoEnvironmentMeansNoImageBasedLightingCode) {
  testContext();
  Scene s = featureScene();
  s.environment.kind = EnvironmentKind::None;
  s.settings.irradiance = Irradiance::Cubemap;  // changes no code without an environment
  render::Renderer r;
  r.setScene(s);
  r.render(32, 32);
  const std::string amb = preprocessed("passes/ambient.comp", r.ambientProgram().defines);
  ASSERT_TRUE(has(amb, "void main"));
  EXPECT_FALSE(has(amb, "t_radiance,"));
  EXPECT_FALSE(has(amb, "evalSH9Irradiance(sh"));
  EXPECT_FALSE(has(amb, "t_irradiance,"));
  s.environment.kind = EnvironmentKind::Uniform;
  render::Renderer r2;
  r2.setScene(s);
  r2.render(32, 32);
  const std::string amb2 = preprocessed("passes/ambient.comp", r2.ambientProgram().defines);
  EXPECT_TRUE(has(amb2, "textureLod(t_radiance,"));
  EXPECT_TRUE(has(amb2, "textureLod(t_irradiance,"));
}

// Tolerance: the two builds run the same arithmetic on the same data, but the compiler may
// schedule it differently; allow 2 half-float steps (2^-9 relative) plus 1e-4 absolute, and where
// the two G-buffer programs rounded a base color to adjacent sRGB codes, that code's step
// (baseColorStep).
TEST(Variants, SpecializedRendersLikeUber) {
  testContext();
  Scene s = featureScene();
  Scene u = s;
  u.settings.uber = true;
  render::Renderer rs, ru;
  rs.setScene(s);
  ru.setScene(u);
  rs.render(128, 128);
  ru.render(128, 128);
  const ImageRGBf a = rs.readHdr(), b = ru.readHdr();
  const GBufferReadback ga = rs.readGBuffer(), gb = ru.readGBuffer();
  ASSERT_EQ(a.px.size(), b.px.size());
  double max_rel = 0.0, sum = 0.0;
  size_t bad = 0, rounded = 0;
  for (size_t i = 0; i < a.px.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double x = a.px[i][c], y = b.px[i][c];
      ASSERT_TRUE(std::isfinite(x) && std::isfinite(y));
      sum += y;
      const double err = std::abs(x - y);
      const double step = baseColorStep(ga, gb, i, c);
      rounded += step > 0.0;
      if (step == 0.0) max_rel = std::max(max_rel, err / std::max(std::abs(y), 1e-3));
      if (err > 1e-4 + std::abs(y) * (2.0 / 512.0 + step)) ++bad;
    }
  }
  EXPECT_GT(sum, 1.0);  // the frame is not black
  EXPECT_EQ(bad, 0u) << "max relative difference where the base colors agree " << max_rel << "; "
                     << rounded << " channel values of another base color code";
  // The uber G-buffer is one program; the specialized one has one per feature set.
  EXPECT_EQ(ru.gbufferPrograms().size(), 1u);
  EXPECT_EQ(rs.gbufferPrograms().size(), 4u);
}

TEST(Variants, ManifestListsTheFramesProgramsWithReasons) {
  testContext();
  Scene s = featureScene();
  s.settings.culling = Culling::Tiled;  // its two lights would get brute force (culling auto)
  render::Renderer r;
  r.setScene(s);
  r.render(32, 32);
  const render::Manifest m = r.manifest();
  EXPECT_EQ(m.key, r.variantKey().text());
  for (const char* name : {"gbuffer", "light_cull", "light", "ambient", "tonemap"}) {
    EXPECT_NE(findProgram(m, name), nullptr) << name;
  }
  for (const auto& p : m.programs) {
    EXPECT_TRUE(p.from_binary_cache ? p.cache_load_ms > 0.0 : p.compile_ms + p.link_ms > 0.0)
        << p.name;
    EXPECT_FALSE(p.stages.empty()) << p.name;
  }
  const auto* light = findProgram(m, "light");
  ASSERT_NE(light, nullptr);
  auto reason = [](const gl::VariantInfo& p, const std::string& prefix) {
    for (const auto& r : p.reasons) {
      if (r.rfind(prefix, 0) == 0) return r;
    }
    return std::string();
  };
  EXPECT_EQ(reason(*light, "HV_HAS_TUBE_LIGHTS"), "HV_HAS_TUBE_LIGHTS=0: no tube lights");
  EXPECT_EQ(reason(*light, "HV_HAS_SPHERE_LIGHTS"), "HV_HAS_SPHERE_LIGHTS=1: 1 sphere light");
  const auto& key = r.variantKey();
  const std::string floor_name =
      "gbuffer " + key.material_variants[size_t(key.material_variant[0])].text();
  const auto* floor = findProgram(m, floor_name);
  ASSERT_NE(floor, nullptr) << floor_name;
  EXPECT_EQ(reason(*floor, "HV_MAT_NORMAL_MAP"), "HV_MAT_NORMAL_MAP=1: material floor");

  // One more sphere light: the same program (same defines), its reason updated.
  s.lights.push_back(s.lights[1]);
  r.updateLights();
  r.render(32, 32);
  const render::Manifest m2 = r.manifest();
  const auto* light2 = findProgram(m2, "light");
  ASSERT_NE(light2, nullptr);
  EXPECT_EQ(light2->key, light->key);
  EXPECT_EQ(reason(*light2, "HV_HAS_SPHERE_LIGHTS"), "HV_HAS_SPHERE_LIGHTS=1: 2 sphere lights");

  // A program not used in the last frame leaves the manifest: the debug view's.
  r.render(32, 32, render::DebugView::Normal);
  EXPECT_NE(findProgram(r.manifest(), "debug_view"), nullptr);
  EXPECT_EQ(findProgram(r.manifest(), "tonemap"), nullptr);
  r.render(32, 32);
  EXPECT_EQ(findProgram(r.manifest(), "debug_view"), nullptr);
}

TEST(Variants, BinaryCacheRoundTripsOrSaysUnsupported) {
  testContext();
  const fs::path dir = fs::temp_directory_path() / "hv_test_program_binaries";
  fs::remove_all(dir);
  gl::ProgramDesc d{"ambient test", {{GL_COMPUTE_SHADER, "passes/ambient.comp"}}, {}};
  gl::ProgramCache first;
  first.setBinaryCacheDir(dir);
  first.get(d);
  GLint formats = 0;
  glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
  if (formats == 0) {
    EXPECT_FALSE(first.binaryCacheEnabled());
    EXPECT_EQ(first.binaryCacheStatus(),
              "unsupported by driver (GL_NUM_PROGRAM_BINARY_FORMATS = 0)");
    EXPECT_FALSE(first.variants().at(0).from_binary_cache);
    EXPECT_FALSE(fs::exists(dir));
    return;
  }
  ASSERT_TRUE(first.binaryCacheEnabled());
  EXPECT_TRUE(first.variants().at(0).binary_saved);
  const fs::path file = first.binaryCachePath(d);
  ASSERT_TRUE(fs::exists(file));
  gl::ProgramCache second;
  second.setBinaryCacheDir(dir);
  GLint linked = GL_FALSE;
  glGetProgramiv(second.get(d), GL_LINK_STATUS, &linked);
  EXPECT_EQ(linked, GL_TRUE);
  EXPECT_TRUE(second.variants().at(0).from_binary_cache);
  EXPECT_EQ(second.binaryHits(), 1u);

  // A corrupted file is ignored with a log line, and the program is compiled again.
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(40);
    const char junk[8] = {'j', 'u', 'n', 'k', 'j', 'u', 'n', 'k'};
    f.write(junk, 8);
  }
  std::vector<std::string> lines;
  auto old = log::setSink([&](log::Level, std::string_view m) { lines.emplace_back(m); });
  gl::ProgramCache third;
  third.setBinaryCacheDir(dir);
  third.get(d);
  log::setSink(old);
  EXPECT_FALSE(third.variants().at(0).from_binary_cache);
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines[0].find("ignoring"), std::string::npos) << lines[0];
  fs::remove_all(dir);
}

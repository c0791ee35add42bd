// Shadow-map pass. In: the scene's geometry and its shadowed lights. Out: the atlas (a depth cube
// map array, six layers per light: the distance from the light's center over its culling radius)
// and each light's cube in GpuLight.shadow_cube. A cube is rendered again only when its light's
// shape or place, the casters' transforms or alpha masks, the scene or the map size changed.
#include <cstring>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "halfvec/shading/light_gpu.hpp"
#include "passes.hpp"
#include "pipeline_state.hpp"
#include "shadow_pass.hpp"

namespace hv::render {

namespace {

// Hash (FNV-1a) of what the maps are rendered from besides the lights: every object's
// transform (a caster that moved) and what makes a material's triangles cut holes in them (its
// alpha mode, cutoff, alpha, base colour texture and vertex colour use).
uint64_t castersHash(const Scene& scene) {
  uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  for (const Object& o : scene.objects) mix(glm::value_ptr(o.transform), sizeof(glm::mat4));
  for (const Material& m : scene.materials) {
    const bool masked = m.alpha_mode == AlphaMode::Mask;
    mix(&masked, sizeof masked);
    if (!masked) continue;
    const float f[2] = {m.alpha_cutoff, m.base_alpha};
    const int t[3] = {m.base_color_tex.image, m.base_color_tex.texcoord, int(m.vertex_color)};
    mix(f, sizeof f);
    mix(t, sizeof t);
  }
  return h ^ scene.objects.size();
}

// Masked draws (alphaMode MASK) go through the variant of the pass that samples the base
// colour's alpha (shadow.frag); it is compiled only for a scene that has one.
bool maskedDraw(const Scene& scene, const DrawItem& d) {
  return scene.materials[size_t(d.material)].alpha_mode == AlphaMode::Mask;
}

gl::ProgramDesc shadowProgram(bool masked) {
  gl::ProgramDesc desc{
      masked ? "shadow_masked" : "shadow",
      {{GL_VERTEX_SHADER, "passes/shadow.vert"}, {GL_FRAGMENT_SHADER, "passes/shadow.frag"}},
      {}};
  if (masked) {
    desc.defines.push_back({"HV_SHADOW_ALPHA_MASK", "1"});
    desc.reasons["HV_SHADOW_ALPHA_MASK"] = "the scene has alpha-masked materials (alphaMode MASK)";
  }
  return desc;
}

// The six faces in the order of GL's cube map layers (+X, -X, +Y, -Y, +Z, -Z), each a view
// looking along the face's axis with the up vector that makes the rendered image the face as
// GL's cube map lookup addresses it (OpenGL 4.5 core, table 8.19).
struct Face {
  glm::vec3 dir, up;
};
constexpr Face kFaces[6] = {{{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}},
                            {{0, 1, 0}, {0, 0, 1}},  {{0, -1, 0}, {0, 0, -1}},
                            {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}};

}  // namespace

void ShadowMaps::ensureAtlas(int size, size_t cubes) {
  if (atlas_ && size == size_ && cubes <= layers_) return;
  size_ = size;
  layers_ = cubes;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_CUBE_MAP_ARRAY, 1, &id);
  atlas_ = gl::Texture(id, "shadow atlas (depth cube map array)");
  glTextureStorage3D(id, 1, GL_DEPTH_COMPONENT32F, size, size, GLsizei(6 * cubes));
  cubes_.assign(cubes, CubeKey{});
  if (!fbo_) {
    GLuint f = 0;
    glCreateFramebuffers(1, &f);
    fbo_ = gl::Framebuffer(f, "shadow map face");
    glNamedFramebufferDrawBuffer(f, GL_NONE);
    glNamedFramebufferReadBuffer(f, GL_NONE);
  }
  if (!raw_) {
    raw_ = gl::createSampler("shadow atlas: raw distance, nearest");
    glSamplerParameteri(raw_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    compare_ = gl::createSampler("shadow atlas: depth comparison, bilinear");
    glSamplerParameteri(compare_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(compare_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(compare_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(compare_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    for (GLuint s : {raw_.id(), compare_.id()}) {
      glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glSamplerParameteri(s, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    }
  }
}

void ShadowMaps::renderCube(const PassContext& ctx, const Input& in, gl::PassBindings& b,
                            size_t cube, const Light& light, float far) {
  const float near_plane = std::max(1e-3f, 1e-6f * far);
  const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, near_plane, far);
  const glm::vec3 p = light.position;
  const auto& draws = in.gpu.draws();
  bool any_masked = false;
  for (const DrawItem& d : draws) any_masked = any_masked || maskedDraw(in.scene, d);
  for (int f = 0; f < 6; ++f) {
    glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, atlas_.id(), 0,
                                   GLint(cube * 6 + size_t(f)));
    const float one = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
    const glm::mat4 view_proj = proj * glm::lookAt(p, p + kFaces[f].dir, kFaces[f].up);
    // The opaque draws, then (a second program) the masked ones with their materials.
    for (const bool masked : {false, true}) {
      if (masked && !any_masked) break;
      b.use(ctx.programs.get(shadowProgram(masked)));
      glUniform4f(HV_LOC_SHADOW_LIGHT, p.x, p.y, p.z, 1.0f / far);
      glUniformMatrix4fv(HV_LOC_SHADOW_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(view_proj));
      int bound_material = -1;
      for (const DrawItem& d : draws) {
        if (maskedDraw(in.scene, d) != masked) continue;
        if (masked && d.material != bound_material) {
          bound_material = d.material;
          b.uniformRange(HV_UBO_MATERIAL, in.gpu.materialBuffer(),
                         GLintptr(size_t(d.material) * in.gpu.materialStride()),
                         GLsizeiptr(sizeof(GpuMaterial)));
          const BoundTexture base = in.gpu.materialTextures(d.material)[0];
          b.texture(HV_UNIT_MATERIAL_TEXTURES, base.texture, base.sampler);
        }
        glUniformMatrix4fv(HV_LOC_MODEL, 1, GL_FALSE,
                           glm::value_ptr(in.scene.objects[size_t(d.object)].transform));
        glDrawElementsBaseVertex(
            GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(size_t(d.first_index) * sizeof(uint32_t)), d.base_vertex);
      }
    }
  }
}

ShadowMaps::Stats ShadowMaps::run(const PassContext& ctx, const Input& in) {
  gl::ScopedPass pass(ctx.timer, "shadows");
  const ShadowAssignment a = assignShadowMaps(in.scene.lights, shadowAtlasCapacity(in.map_size));
  Stats st;
  st.maps = a.maps.size();
  st.over_budget = a.over_budget;
  // The warning names the lights beyond the budget, once per change of that list.
  const std::string warning = overBudgetWarning(in.scene.lights, a, in.map_size);
  if (warning != warned_ && !warning.empty()) logShadowWarning(warning);
  warned_ = warning;
  // shadow_cube of every light: its cube + 1 (0: no map), written when the buffer was re-uploaded
  // (GpuScene::updateLights writes 0) or a light's cube changed.
  if (written_for_ != &in.gpu || written_version_ != in.lights_version ||
      written_cube_.size() != a.layer.size()) {
    written_cube_.assign(a.layer.size(), 0u);
    written_for_ = &in.gpu;
    written_version_ = in.lights_version;
  }
  for (size_t i = 0; i < a.layer.size(); ++i) {
    const uint32_t cube = uint32_t(a.layer[i] + 1);
    if (cube == written_cube_[i]) continue;
    written_cube_[i] = cube;
    glNamedBufferSubData(in.gpu.lightBuffer(),
                         GLintptr(i * sizeof(GpuLight) + offsetof(GpuLight, shadow_cube)),
                         sizeof cube, &cube);
  }
  if (a.maps.empty()) return st;
  ensureAtlas(in.map_size, a.maps.size());
  const uint64_t casters = castersHash(in.scene);
  // The pass's bindings (the masked casters' material block and base colour texture), opened
  // with the first cube rendered: a frame whose maps are all cached binds nothing.
  std::optional<gl::PassBindings> bindings;
  bool bound = false;
  for (size_t c = 0; c < a.maps.size(); ++c) {
    const Light& l = in.scene.lights[a.maps[c]];
    const GpuLight g = packLight(l);
    const float far = glsl::lightCullRadius(toGlsl(g));
    CubeKey key;
    key.light = {g.position_radius.x, g.position_radius.y, g.position_radius.z,
                 g.position_radius.w, g.axis_length.x,     g.axis_length.y,
                 g.axis_length.z,     g.axis_length.w,     far};
    key.casters = casters;
    key.size = in.map_size;
    if (cubes_[c] == key) continue;
    if (!bound) {
      PipelineState s;
      s.depth_test = true;
      s.depth_write = true;
      s.depth_func = GL_LESS;
      applyState(s);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
      glViewport(0, 0, in.map_size, in.map_size);
      glBindVertexArray(in.gpu.vertexArray());
      bindings.emplace(kPassSlots, "shadows");
      bound = true;
    }
    renderCube(ctx, in, *bindings, c, l, far);
    cubes_[c] = key;
    ++st.rendered;
  }
  if (bound) {
    bindings.reset();  // releases and checks what the pass bound
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    applyState(PipelineState{});
  }
  return st;
}

void ShadowMaps::bind() const {
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glBindTextureUnit(HV_UNIT_SHADOW_DEPTH, atlas_.id());
  glBindSampler(HV_UNIT_SHADOW_DEPTH, raw_.id());
  glBindTextureUnit(HV_UNIT_SHADOW_COMPARE, atlas_.id());
  glBindSampler(HV_UNIT_SHADOW_COMPARE, compare_.id());
}

void ShadowMaps::unbind() {
  for (GLuint u : {GLuint(HV_UNIT_SHADOW_DEPTH), GLuint(HV_UNIT_SHADOW_COMPARE)}) {
    glBindTextureUnit(u, 0);
    glBindSampler(u, 0);
  }
}

}  // namespace hv::render

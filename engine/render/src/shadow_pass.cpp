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

gl::ProgramDesc shadowProgram(bool masked, bool ortho = false) {
  gl::ProgramDesc desc{
      std::string(ortho ? "sun_" : "") + (masked ? "shadow_masked" : "shadow"),
      {{GL_VERTEX_SHADER, "passes/shadow.vert"}, {GL_FRAGMENT_SHADER, "passes/shadow.frag"}},
      {}};
  if (masked) {
    desc.defines.push_back({"HV_SHADOW_ALPHA_MASK", "1"});
    desc.reasons["HV_SHADOW_ALPHA_MASK"] = "the scene has alpha-masked materials (alphaMode MASK)";
  }
  if (ortho) {
    desc.defines.push_back({"HV_SHADOW_ORTHO", "1"});
    desc.reasons["HV_SHADOW_ORTHO"] =
        "a directional light's map: the rasterized depth of an orthographic view";
  }
  return desc;
}

// A directional light's map (GpuSunShadow, gpu_records.glsl): a square across the light's
// travel direction F holding the casters' world bounds (the union of the draws' boxes), its near
// plane upstream of all of them, padded by two texels across and 1% along F. One map over the
// whole scene: no cascades, so its texels are the scene's extent over the map size.
struct SunFrame {
  GpuSunShadow map;
  glm::mat4 view_proj;  // world -> clip of the orthographic render (GL's -1..1 depth)
};
SunFrame sunFrame(const Scene& scene, const GpuScene& gpu, const Light& light, int size) {
  glm::vec3 F = light.direction;
  const float len = glm::length(F);
  F = std::isfinite(len) && len > 1e-20f ? F / len : glm::vec3(0, -1, 0);
  const glm::vec3 helper = std::abs(F.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 R = glm::normalize(glm::cross(F, helper));
  const glm::vec3 U = glm::cross(R, F);
  glm::vec3 lo(3e38f), hi(-3e38f);  // light-space bounds (along R, U, F)
  for (const DrawItem& d : gpu.draws()) {
    const glm::mat4& m = scene.objects[size_t(d.object)].transform;
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner =
          d.center + d.half_extent * glm::vec3(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
      const glm::vec3 w = glm::vec3(m * glm::vec4(corner, 1.0f));
      const glm::vec3 l(glm::dot(w, R), glm::dot(w, U), glm::dot(w, F));
      lo = glm::min(lo, l);
      hi = glm::max(hi, l);
    }
  }
  if (!(lo.x <= hi.x)) lo = hi = glm::vec3(0.0f);  // no geometry: an empty 1 m map
  float extent = std::max({hi.x - lo.x, hi.y - lo.y, 1e-3f});
  extent *= 1.0f + 4.0f / float(std::max(size, 1));
  const float range = std::max(hi.z - lo.z, 1e-3f) * 1.02f + 1e-3f;
  const glm::vec3 origin = R * (0.5f * (lo.x + hi.x)) + U * (0.5f * (lo.y + hi.y)) +
                           F * (lo.z - 0.01f * (hi.z - lo.z) - 5e-4f);
  SunFrame f;
  f.map.origin_inv_range = glm::vec4(origin, 1.0f / range);
  f.map.right_inv_extent = glm::vec4(R, 1.0f / extent);
  f.map.up_texel = glm::vec4(U, extent / float(std::max(size, 1)));
  const float sigma = 0.5f * std::clamp(light.angular_diameter, 0.0f, kMaxAngularDiameter);
  f.map.forward_tan = glm::vec4(F, std::tan(sigma));
  // clip = (2 (P - o).R / extent, 2 (P - o).U / extent, 2 (P - o).F / range - 1): the rows.
  const float sx = 2.0f / extent, sz = 2.0f / range;
  glm::mat4 vp(0.0f);
  for (int c = 0; c < 3; ++c) {
    vp[c][0] = sx * R[c];
    vp[c][1] = sx * U[c];
    vp[c][2] = sz * F[c];
  }
  vp[3][0] = -sx * glm::dot(R, origin);
  vp[3][1] = -sx * glm::dot(U, origin);
  vp[3][2] = -sz * glm::dot(F, origin) - 1.0f;
  vp[3][3] = 1.0f;
  f.view_proj = vp;
  return f;
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

namespace {

// Every caster drawn with view_proj into the bound framebuffer layer: the opaque draws, then (a
// second program) the masked ones with their materials. `light`: the cube's center and 1 / far
// (shadow.frag's distance), unused by the orthographic program (rasterized depth).
void drawCasters(const PassContext& ctx, const ShadowMaps::Input& in, gl::PassBindings& b,
                 const glm::mat4& view_proj, const glm::vec4* light) {
  const auto& draws = in.gpu.draws();
  bool any_masked = false;
  for (const DrawItem& d : draws) any_masked = any_masked || maskedDraw(in.scene, d);
  for (const bool masked : {false, true}) {
    if (masked && !any_masked) break;
    b.use(ctx.programs.get(shadowProgram(masked, light == nullptr)));
    if (light) glUniform4f(HV_LOC_SHADOW_LIGHT, light->x, light->y, light->z, light->w);
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

}  // namespace

void ShadowMaps::renderCube(const PassContext& ctx, const Input& in, gl::PassBindings& b,
                            size_t cube, const Light& light, float far) {
  const float near_plane = std::max(1e-3f, 1e-6f * far);
  const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, near_plane, far);
  const glm::vec3 p = light.position;
  const glm::vec4 center(p, 1.0f / far);
  for (int f = 0; f < 6; ++f) {
    glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, atlas_.id(), 0,
                                   GLint(cube * 6 + size_t(f)));
    const float one = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
    drawCasters(ctx, in, b, proj * glm::lookAt(p, p + kFaces[f].dir, kFaces[f].up), &center);
  }
}

void ShadowMaps::renderSun(const PassContext& ctx, const Input& in, gl::PassBindings& b,
                           size_t layer, const glm::mat4& view_proj) {
  glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, sun_maps_.id(), 0, GLint(layer));
  const float one = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
  drawCasters(ctx, in, b, view_proj, nullptr);
}

void ShadowMaps::ensureSunMaps(int size, size_t layers) {
  if (sun_maps_ && size == sun_size_ && layers <= sun_layers_) return;
  sun_size_ = size;
  sun_layers_ = layers;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  sun_maps_ = gl::Texture(id, "directional shadow maps (depth 2D array)");
  glTextureStorage3D(id, 1, GL_DEPTH_COMPONENT32F, size, size, GLsizei(layers));
  suns_.assign(layers, SunKey{});
  if (!sun_block_) {
    sun_block_ = gl::createBuffer("directional shadow maps: frames (GpuSunShadow)",
                                  kMaxDirectionalLights * sizeof(GpuSunShadow));
  }
}

// shadow_cube of every light: its cube or sun layer + 1 (0: no map), written when the buffer was
// re-uploaded (GpuScene::updateLights writes 0) or a light's map changed.
void ShadowMaps::writeShadowSlots(const Input& in, const ShadowAssignment& a) {
  if (written_for_ != &in.gpu || written_version_ != in.lights_version ||
      written_cube_.size() != a.layer.size()) {
    written_cube_.assign(a.layer.size(), 0u);
    written_for_ = &in.gpu;
    written_version_ = in.lights_version;
  }
  for (size_t i = 0; i < a.layer.size(); ++i) {
    const uint32_t cube = a.shadowSlot(i);
    if (cube == written_cube_[i]) continue;
    written_cube_[i] = cube;
    glNamedBufferSubData(in.gpu.lightBuffer(),
                         GLintptr(i * sizeof(GpuLight) + offsetof(GpuLight, shadow_cube)),
                         sizeof cube, &cube);
  }
}

ShadowMaps::Stats ShadowMaps::run(const PassContext& ctx, const Input& in) {
  gl::ScopedPass pass(ctx.timer, "shadows");
  // The lights as the light pass has them (the environment's sun last, where it is a light).
  const std::vector<Light>& lights = in.gpu.lights();
  const size_t capacity = shadowLightCapacity(in.map_size, in.mask);
  const ShadowAssignment a = assignShadowMaps(lights, capacity);
  Stats st;
  st.maps = a.maps.size();
  st.over_budget = a.over_budget;
  for (size_t i : a.maps) st.mapped.push_back(uint32_t(i));
  for (size_t i : a.suns) st.mapped.push_back(uint32_t(i));
  // The warning names the lights beyond the budget, once per change of that list.
  const std::string warning =
      overBudgetWarning(lights, a, in.map_size, capacity < shadowAtlasCapacity(in.map_size));
  if (warning != warned_ && !warning.empty()) logShadowWarning(warning);
  warned_ = warning;
  writeShadowSlots(in, a);
  // Both map arrays exist whenever shadows are drawn (one layer at least), so that the passes'
  // lookups always sample a complete texture of their type.
  ensureAtlas(in.map_size, std::max<size_t>(a.maps.size(), 1));
  ensureSunMaps(in.map_size, std::max<size_t>(a.suns.size(), 1));
  const uint64_t casters = castersHash(in.scene);
  // The pass's bindings (the masked casters' material block and base colour texture), opened
  // with the first cube rendered: a frame whose maps are all cached binds nothing.
  std::optional<gl::PassBindings> bindings;
  bool bound = false;
  const auto open = [&] {
    PipelineState ps;
    ps.depth_test = true;
    ps.depth_write = true;
    ps.depth_func = GL_LESS;
    applyState(ps);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, in.map_size, in.map_size);
    glBindVertexArray(in.gpu.vertexArray());
    bindings.emplace(kPassSlots, "shadows");
    bound = true;
  };
  for (size_t c = 0; c < a.maps.size(); ++c) {
    const Light& l = lights[a.maps[c]];
    const GpuLight g = packLight(l);
    const float far = glsl::lightCullRadius(toGlsl(g));
    CubeKey key;
    key.light = {g.position_radius.x, g.position_radius.y, g.position_radius.z,
                 g.position_radius.w, g.axis_length.x,     g.axis_length.y,
                 g.axis_length.z,     g.axis_length.w,     far};
    key.casters = casters;
    key.size = in.map_size;
    if (cubes_[c] == key) continue;
    if (!bound) open();
    renderCube(ctx, in, *bindings, c, l, far);
    cubes_[c] = key;
    ++st.rendered;
  }
  // The directional lights' maps, each re-rendered when its frame (direction, disk, the casters'
  // bounds) or the casters changed; their frames go to the uniform block the lookups read.
  std::array<GpuSunShadow, kMaxDirectionalLights> frames{};
  for (size_t c = 0; c < a.suns.size(); ++c) {
    const SunFrame f = sunFrame(in.scene, in.gpu, lights[a.suns[c]], in.map_size);
    frames[c] = f.map;
    SunKey key;
    std::memcpy(key.frame.data(), &f.map, sizeof f.map);
    key.casters = casters;
    key.size = in.map_size;
    if (suns_[c] == key) continue;
    if (!bound) open();
    renderSun(ctx, in, *bindings, c, f.view_proj);
    suns_[c] = key;
    ++st.rendered;
  }
  st.maps += a.suns.size();
  glNamedBufferSubData(sun_block_.id(), 0, sizeof frames, frames.data());
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

// Ambient pass and the environment's GPU resources. In: G-buffer, the IBL bake (prefiltered
// radiance cube, env BRDF table, SH9, irradiance cube). Out: ambient light added to the HDR target,
// the environment drawn on background pixels.
#include "halfvec/ibl/ibl.hpp"
#include "pipeline_state.hpp"
#include "halfvec/render/renderer.hpp"
#include "targets.hpp"

namespace hv::render {

namespace {
struct alignas(16) EnvironmentBlock {
  glm::vec4 sh[9];
  glm::vec4 env;  // max mip, table size, present, unused
};

gl::Texture uploadCube(const char* name, const CubeMapF& c) {
  gl::Texture t = gl::createTextureCube(name, GL_RGBA16F, c.size, c.mipCount());
  for (int m = 0; m < c.mipCount(); ++m) {
    const int s = c.mipSize(m);
    for (int f = 0; f < 6; ++f) {
      glTextureSubImage3D(t.id(), m, 0, 0, f, s, s, 1, GL_RGB, GL_FLOAT, c.levels[m][f].data());
    }
  }
  glTextureParameteri(t.id(), GL_TEXTURE_MAX_LEVEL, c.mipCount() - 1);
  return t;
}
}  // namespace

void Renderer::setEnvironment(const Scene& scene) {
  env_ = std::make_unique<Environment>();
  Environment& e = *env_;
  e.block = gl::createBuffer("environment uniforms", sizeof(EnvironmentBlock));
  e.trilinear = gl::createSampler("environment trilinear");
  glSamplerParameteri(e.trilinear.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glSamplerParameteri(e.trilinear.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum w : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
    glSamplerParameteri(e.trilinear.id(), w, GL_CLAMP_TO_EDGE);
  }
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  EnvironmentBlock block{};
  if (scene.environment.kind != EnvironmentKind::None) {
    BakeOptions opt;
    opt.brdf = BrdfConfig::fromSettings(scene.settings);
    opt.irradiance_size = scene.settings.irradiance == Irradiance::Cubemap ? 32 : 0;
    const IblBake bake = bakeEnvironment(scene.environment, opt);
    e.timings = bake.timings;
    e.radiance = uploadCube("prefiltered radiance", bake.radiance);
    if (bake.irradiance.size > 0) e.irradiance = uploadCube("irradiance", bake.irradiance);
    e.env_brdf = gl::createTexture2D("environment BRDF (scale, bias)", GL_RG16F, bake.env_brdf_size,
                                     bake.env_brdf_size);
    glTextureSubImage2D(e.env_brdf.id(), 0, 0, 0, bake.env_brdf_size, bake.env_brdf_size, GL_RG,
                        GL_FLOAT, bake.env_brdf.data());
    for (int i = 0; i < 9; ++i) block.sh[i] = glm::vec4(bake.sh[i], 0.0f);
    block.env =
        glm::vec4(float(bake.radiance.mipCount() - 1), float(bake.env_brdf_size), 1.0f, 0.0f);
    e.present = true;
  }
  glNamedBufferSubData(e.block.id(), 0, sizeof block, &block);
}

const BakeTimings* Renderer::environmentTimings() const {
  return env_ && env_->present ? &env_->timings : nullptr;
}

void Renderer::ambientPass() {
  gl::ScopedPass pass(timer_, "ambient");
  applyState(PipelineState{});
  Targets& t = *targets_;
  // Defines from the variant key: environment presence, shading models, IBL options.
  const GLuint prog = programs_.get(ambient_desc_);
  glUseProgram(prog);
  const GLuint inputs[4] = {t.base_cavity.id(), t.material.id(), t.normal.id(), t.depth.id()};
  for (GLuint u = 0; u < 4; ++u) {
    glBindTextureUnit(u, inputs[u]);
    glBindSampler(u, nearest_.id());
  }
  const Environment& e = *env_;
  // Units 5-7 always hold a texture of the right type (GL requires it for a sampled unit).
  const GLuint radiance = e.radiance ? e.radiance.id() : fallbackCube();
  glBindTextureUnit(5, radiance);
  glBindTextureUnit(6, e.env_brdf ? e.env_brdf.id() : t.base_cavity.id());
  glBindTextureUnit(7, e.irradiance ? e.irradiance.id() : radiance);
  for (GLuint u = 5; u < 8; ++u) glBindSampler(u, e.trilinear.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, e.block.id());
  glBindImageTexture(0, t.hdr.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
  glDispatchCompute((t.width + kTileSize - 1) / kTileSize, (t.height + kTileSize - 1) / kTileSize,
                    1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  for (GLuint u = 0; u < 8; ++u) glBindSampler(u, 0);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
  glUseProgram(0);
}

GLuint Renderer::fallbackCube() {
  if (!fallback_cube_) {
    fallback_cube_ = gl::createTextureCube("black cube", GL_RGBA16F, 1, 1);
    const float black[4] = {0, 0, 0, 0};
    glClearTexImage(fallback_cube_.id(), 0, GL_RGBA, GL_FLOAT, black);
  }
  return fallback_cube_.id();
}

}  // namespace hv::render

// Ambient pass and the environment's GPU resources. In: G-buffer, the IBL bake (prefiltered
// radiance cube, env BRDF table, SH9, irradiance cube). Out: ambient light added to the HDR target,
// the environment drawn on background pixels.
#include "halfvec/ibl/sky_sun.hpp"
#include "passes.hpp"
#include "pipeline_state.hpp"

namespace hv::render {

namespace {
// The members of shaders/common/environment_block.glsl, the list ambient.comp declares the block
// from.
struct alignas(16) EnvironmentBlock {
#define HV_BLOCK_MEMBER(type, name) glm::type name;
#define HV_BLOCK_ARRAY(type, name, count) glm::type name[count];
#include "halfvec/shaders/common/environment_block.glsl"
#undef HV_BLOCK_ARRAY
#undef HV_BLOCK_MEMBER
};
static_assert(sizeof(EnvironmentBlock) == 10 * 16, "EnvironmentBlock must match std140 layout");
static_assert(offsetof(EnvironmentBlock, env) == 9 * 16);

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

GpuEnvironment::GpuEnvironment(const Scene& scene) {
  block_ = gl::createBuffer("environment uniforms", sizeof(EnvironmentBlock));
  trilinear_ = gl::createSampler("environment trilinear");
  glSamplerParameteri(trilinear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glSamplerParameteri(trilinear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum w : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
    glSamplerParameteri(trilinear_.id(), w, GL_CLAMP_TO_EDGE);
  }
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  EnvironmentBlock block{};
  if (scene.environment.kind != EnvironmentKind::None) {
    BakeOptions opt;
    opt.brdf = BrdfConfig::fromSettings(scene.settings);
    opt.irradiance_size = scene.settings.irradiance == Irradiance::Cubemap ? 32 : 0;
    opt.sky.sun_disk = !skySunIsLight(scene);  // else the light pass draws it (GpuScene)
    const IblBake bake = bakeEnvironment(scene.environment, opt);
    timings_ = bake.timings;
    radiance_ = uploadCube("prefiltered radiance", bake.radiance);
    if (bake.irradiance.size > 0) irradiance_ = uploadCube("irradiance", bake.irradiance);
    env_brdf_ = gl::createTexture2D("environment BRDF (scale, bias)", GL_RG16F, bake.env_brdf_size,
                                    bake.env_brdf_size);
    glTextureSubImage2D(env_brdf_.id(), 0, 0, 0, bake.env_brdf_size, bake.env_brdf_size, GL_RG,
                        GL_FLOAT, bake.env_brdf.data());
    for (int i = 0; i < 9; ++i) block.sh[i] = glm::vec4(bake.sh[i], 0.0f);
    block.env =
        glm::vec4(float(bake.radiance.mipCount() - 1), float(bake.env_brdf_size), 1.0f, 0.0f);
    present_ = true;
  } else {
    black_cube_ = gl::createTextureCube("black cube", GL_RGBA16F, 1, 1);
    const float black[4] = {0, 0, 0, 0};
    glClearTexImage(black_cube_.id(), 0, GL_RGBA, GL_FLOAT, black);
  }
  glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
}

void GpuEnvironment::bind(gl::PassBindings& b, GLuint fallback_2d,
                          const EnvironmentUnits& units) const {
  // The units always hold a texture of the right type (GL requires it for a sampled unit).
  const GLuint radiance = radiance_ ? radiance_.id() : black_cube_.id();
  b.texture(units.radiance, radiance, trilinear_.id());
  b.texture(units.env_brdf, env_brdf_ ? env_brdf_.id() : fallback_2d, trilinear_.id());
  b.texture(units.irradiance, irradiance_ ? irradiance_.id() : radiance, trilinear_.id());
  b.uniform(HV_UBO_ENVIRONMENT, block_.id());
}

void runAmbientPass(const PassContext& ctx, const AmbientPassInput& in, GLuint hdr, int width,
                    int height) {
  gl::ScopedPass pass(ctx.timer, "ambient");
  applyState(PipelineState{});
  // Defines from the variant key: environment presence, shading models, IBL options.
  gl::PassBindings b(kPassSlots, "ambient");
  b.use(ctx.programs.get(in.program));
  bindGBuffer(b, in.gbuffer, ctx.nearest);
  in.environment.bind(b, in.gbuffer.base_cavity);
  if (in.ao) {
    b.texture(HV_UNIT_AO, in.ao, ctx.nearest);
    // The AO upsample reads depth texels (texelFetch, unfiltered); the traced specular occlusion
    // reads it bilinearly between them.
    b.texture(HV_UNIT_DEPTH, in.gbuffer.depth, ctx.bilinear);
  }
  b.image(HV_IMAGE_HDR, hdr, GL_READ_WRITE, GL_RGBA16F);
  glDispatchCompute((width + kTileSize - 1) / kTileSize, (height + kTileSize - 1) / kTileSize, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace hv::render

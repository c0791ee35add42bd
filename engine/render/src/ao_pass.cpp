// The AO pass (passes.hpp, AoPass): GTAO's horizon search, then its denoise, at full or half
// resolution (settings.ao_resolution), timed together as "ao".
#include "passes.hpp"
#include "pipeline_state.hpp"

namespace hv::render {

namespace {
gl::DefineSet defineSet(const std::vector<KeyDefine>& defs,
                        std::map<std::string, std::string>& reasons) {
  gl::DefineSet d;
  for (const KeyDefine& k : defs) {
    d.push_back({k.name, k.value});
    reasons[k.name] = k.why;
  }
  return d;
}
}  // namespace

void AoPass::setVariant(const VariantKey& key, const Scene& scene) {
  gtao_ = {"gtao", {{GL_COMPUTE_SHADER, "passes/gtao.comp"}}, {}};
  denoise_ = {"ao denoise", {{GL_COMPUTE_SHADER, "passes/ao_denoise.comp"}}, {}};
  gtao_.defines = defineSet(aoDefines(key, scene), gtao_.reasons);
  denoise_.defines = defineSet(aoDefines(key, scene), denoise_.reasons);
}

GLuint AoPass::run(const PassContext& ctx, const GBufferView& gbuffer,
                   const RenderSettings& settings, int width, int height) {
  gl::ScopedPass pass(ctx.timer, "ao");
  applyState(PipelineState{});
  const int scale = settings.ao_resolution == AoResolution::Half ? 2 : 1;
  const int w = (width + scale - 1) / scale, h = (height + scale - 1) / scale;
  if (w != width_ || h != height_ || !raw_) {
    raw_ =
        gl::createTexture2D("ao raw (visibility, inverse distance, bent normal)", GL_RGBA16F, w, h);
    denoised_ = gl::createTexture2D("ao denoised", GL_RGBA16F, w, h);
    width_ = w;
    height_ = h;
  }
  const GLuint groups_x = GLuint((w + kTileSize - 1) / kTileSize);
  const GLuint groups_y = GLuint((h + kTileSize - 1) / kTileSize);
  gl::PassBindings b(kPassSlots, "ao");
  const GLuint gtao = ctx.programs.get(gtao_);
  b.use(gtao);
  glProgramUniform4f(gtao, HV_LOC_AO_PARAMS, settings.ao_radius, float(scale), float(w), float(h));
  bindGBuffer(b, gbuffer, ctx.nearest);
  // The horizon search filters depth bilinearly (gtao.comp, horizonCos); texelFetch ignores it.
  b.texture(HV_UNIT_DEPTH, gbuffer.depth, ctx.bilinear);
  b.image(HV_IMAGE_AO, raw_.id(), GL_WRITE_ONLY, GL_RGBA16F);
  glDispatchCompute(groups_x, groups_y, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  b.texture(HV_UNIT_DEPTH, gbuffer.depth, ctx.nearest);
  const GLuint denoise = ctx.programs.get(denoise_);
  b.use(denoise);
  glProgramUniform4f(denoise, HV_LOC_AO_PARAMS, settings.ao_radius, float(scale), float(w),
                     float(h));
  // The denoise reads the raw target's 2x2 quads as bilinear fetches (ao_denoise.comp).
  b.texture(HV_UNIT_AO, raw_.id(), ctx.bilinear);
  b.image(HV_IMAGE_AO, denoised_.id(), GL_WRITE_ONLY, GL_RGBA16F);
  glDispatchCompute(groups_x, groups_y, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  return denoised_.id();
}

}  // namespace hv::render

// The trade report's first stage: the reference of the exact configuration, cached on disk under
// a hash of everything it depends on (trade_reference.hpp).
#include "trade_reference.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "halfvec/core/output_files.hpp"
#include "halfvec/ibl/ibl.hpp"

namespace hv::eval::trade_detail {

namespace fs = std::filesystem;

namespace {

// Bump whenever engine/reference changes what it computes for the same inputs.
constexpr const char* kReferenceCacheVersion = "trade-reference-v4";

// ---- FNV-1a over the inputs of the reference --------------------------------------------------
struct Hasher {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  template <class T>
  void pod(const T& v) {
    bytes(&v, sizeof v);
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod(v.size());
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    pod(s.size());
    bytes(s.data(), s.size());
  }
};

std::string readText(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream o;
  if (f) o << f.rdbuf();
  return o.str();
}

// Scene content (the file's text and everything the reference reads), size, samples, seed, the
// truth settings and the visibility mode (with visibility, the triangles and alpha inputs that
// occlude, off screen too; without it the key is the one it was before visibility existed).
uint64_t referenceKey(const Scene& scene, const GBufferReadback& gb, const RenderSettings& truth,
                      int samples, uint64_t seed, bool visibility) {
  Hasher k;
  k.text(kReferenceCacheVersion);
  k.text(readText(scene.source_path));
  k.pod(gb.width), k.pod(gb.height);
  k.vec(gb.base_color), k.vec(gb.metallic), k.vec(gb.roughness), k.vec(gb.cavity);
  k.vec(gb.depth), k.vec(gb.normal), k.vec(gb.model);
  const Camera& c = scene.camera;
  k.pod(c.position), k.pod(c.target), k.pod(c.up), k.pod(c.fov_y_deg);
  for (const Light& l : scene.lights) {
    k.pod(l.type), k.pod(l.position), k.pod(l.color), k.pod(l.intensity), k.pod(l.radius);
    k.pod(l.length), k.pod(l.axis), k.pod(l.range);
  }
  const Environment& e = scene.environment;
  k.pod(e.kind), k.text(e.path), k.pod(e.color), k.pod(e.intensity), k.pod(e.rotation_deg);
  k.pod(truth.d), k.pod(truth.v), k.pod(truth.f), k.pod(truth.diffuse);
  k.pod(truth.remap_roughness), k.pod(truth.falloff_plus_one);
  k.pod(truth.energy_compensation), k.pod(truth.specular_occlusion);
  k.pod(samples), k.pod(seed);
  if (visibility) {
    k.text("visibility");
    for (const Object& o : scene.objects) k.pod(o.transform), k.vec(o.meshes);
    for (const Mesh& m : scene.meshes) {
      for (const Vertex& v : m.vertices) k.pod(v.position), k.pod(v.uv0), k.pod(v.uv1);
      k.vec(m.indices), k.pod(m.material);
    }
    for (const Material& m : scene.materials) {
      k.pod(m.alpha_mode), k.pod(m.alpha_cutoff), k.pod(m.base_alpha);
      k.pod(m.base_color_tex.image), k.pod(m.base_color_tex.texcoord);
    }
    for (const ImageData& i : scene.images) k.pod(i.width), k.pod(i.height), k.vec(i.rgba);
  }
  return k.h;
}

std::string defaultCacheDir() {
  return (fs::path(iblCacheDir(BakeOptions{})) / "reference").string();
}

}  // namespace

std::pair<ImageRGBf, ImageRGBf> tradeReference(const Scene& scene, const GBufferReadback& gb,
                                               const TradeOptions& opt, TradeReport& rep,
                                               const Say& say) {
  const int w = rep.width, h = rep.height;
  Scene truth_scene = scene;
  truth_scene.settings = rep.truth;
  const uint64_t key = referenceKey(scene, gb, rep.truth, rep.samples, opt.seed, opt.visibility);
  const fs::path cache =
      opt.cache_dir.empty() ? fs::path(defaultCacheDir()) : fs::path(opt.cache_dir);
  char name[64];
  std::snprintf(name, sizeof name, "reference-%016llx", static_cast<unsigned long long>(key));
  const fs::path img_path = cache / (std::string(name) + ".pfm");
  const fs::path se_path = cache / (std::string(name) + "-se.pfm");
  const fs::path meta_path = cache / (std::string(name) + ".json");
  rep.reference_file = img_path.string();
  ImageRGBf ref, ref_se;
  if (opt.use_cache && fs::exists(img_path) && fs::exists(se_path) && fs::exists(meta_path)) {
    ref = readPfm(img_path.string());
    ref_se = readPfm(se_path.string());
    const auto j = nlohmann::json::parse(readText(meta_path.string()));
    rep.reference.lit_pixels = j.at("lit_pixels").get<size_t>();
    rep.reference.total_samples = j.at("total_samples").get<uint64_t>();
    rep.reference.mean_rel_error = j.at("mean_rel_error").get<double>();
    rep.reference.max_rel_error = j.at("max_rel_error").get<double>();
    rep.reference.seconds = j.at("seconds").get<double>();
    rep.reference_cached =
        ref.width == w && ref.height == h && ref_se.width == w && ref_se.height == h;
    if (rep.reference_cached) say("reference: cached " + img_path.string());
  }
  if (rep.reference_cached) return {std::move(ref), std::move(ref_se)};
  say("reference: " + std::to_string(w) + "x" + std::to_string(h) + ", " +
      std::to_string(rep.samples) + " samples per pixel ...");
  ReferenceOptions ro;
  ro.samples = rep.samples;
  ro.threads = opt.threads;
  ro.seed = opt.seed;
  ro.visibility = opt.visibility;
  const ReferenceResult rr = renderReference(truth_scene, gb, ro);
  rep.reference = rr.stats;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f", rr.stats.seconds);
  say("reference: " + std::string(seconds) + " s");
  if (opt.use_cache) {
    fs::create_directories(cache);
    OutputFiles files;  // the three appear together or not at all (a cache hit needs all)
    writePfm(files.add(img_path).string(), rr.image);
    writePfm(files.add(se_path).string(), rr.std_error);
    nlohmann::ordered_json j = {{"scene", scene.source_path},
                                {"width", w},
                                {"height", h},
                                {"samples", rep.samples},
                                {"visibility", opt.visibility},
                                {"lit_pixels", rr.stats.lit_pixels},
                                {"total_samples", rr.stats.total_samples},
                                {"mean_rel_error", rr.stats.mean_rel_error},
                                {"max_rel_error", rr.stats.max_rel_error},
                                {"seconds", rr.stats.seconds}};
    files.write(meta_path, j.dump(2) + "\n");
    files.commit();
  }
  return {rr.image, rr.std_error};
}

}  // namespace hv::eval::trade_detail

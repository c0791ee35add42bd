// Soak: many frames of many_lights in one process, and many hot reloads of the glTF
// sample through the viewer's SceneReloader, recording memory and live GL objects. Nothing may
// grow once warmed up: live GL objects constant, and the largest heap in use after warm-up within
// 2% (+ 4 MB for the short runs) of the largest during it. The heap in use (mallinfo2: bytes in
// allocated chunks and mmapped blocks, every arena; llvmpipe's textures and buffers are malloc'd
// too) is what a leak grows. Resident memory (RSS) is printed beside it but not asserted: glibc
// keeps freed memory of a thread's arena resident, so RSS steps up once when a worker thread
// first decodes textures in an arena of its own (seen: +108 MB at the 5th reload, flat after)
// without any memory being lost. The driver frees a replaced scene's textures some frames
// late, so a reload sample may hold one more scene's textures: that is allowed for, once. Peaks are
// compared, not single samples (the driver frees the previous scene's objects late). The suite runs
// short versions; scripts/soak.sh runs the long counts (HV_SOAK_FRAMES=3000,
// HV_SOAK_RELOADS=300) and the viewer itself under Xvfb.
#include <gtest/gtest.h>

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/scene_reload.hpp"
#include "halfvec/gl/objects.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "shared_assets.hpp"

namespace fs = std::filesystem;

namespace {

double rssMb() {
  std::ifstream f("/proc/self/statm");
  long pages = 0, resident = 0;
  f >> pages >> resident;
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

int envCount(const char* name, int def) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : def;
}

double heapInUseMb() {
  const struct mallinfo2 m = mallinfo2();
  return double(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
}

// Peak heap in use during and after warm-up: flat within 2% (+ `slack_mb`); the same live GL
// objects. Peak RSS is reported.
struct Track {
  double heap_warm = 0, heap_after = 0, rss_warm = 0, rss_after = 0;
  int gl_warm = -1, gl_after_min = 1 << 30, gl_after_max = -1;
  void sample(bool warmed_up) {
    const double heap = heapInUseMb(), rss = rssMb();
    const int gl = hv::gl::liveCountTotal();
    if (!warmed_up) {
      heap_warm = std::max(heap_warm, heap);
      rss_warm = std::max(rss_warm, rss);
      gl_warm = gl;
    } else {
      heap_after = std::max(heap_after, heap);
      rss_after = std::max(rss_after, rss);
      gl_after_min = std::min(gl_after_min, gl), gl_after_max = std::max(gl_after_max, gl);
    }
  }
  // `pending_mb`: memory the driver may still hold for a replaced scene when a sample is taken.
  void expectFlat(const char* what, double slack_mb, double pending_mb = 0.0) const {
    std::printf(
        "[ soak ] %s: peak heap in use %.1f MB during warm-up, %.1f MB after (%+.2f%%); peak "
        "RSS %.1f MB, %.1f MB after (%+.2f%%); live GL objects %d, after warm-up %d..%d\n",
        what, heap_warm, heap_after, 100.0 * (heap_after / heap_warm - 1.0), rss_warm, rss_after,
        100.0 * (rss_after / rss_warm - 1.0), gl_warm, gl_after_min, gl_after_max);
    EXPECT_LE(heap_after, heap_warm * 1.02 + slack_mb + pending_mb) << what;
    EXPECT_EQ(gl_after_min, gl_warm) << what;
    EXPECT_EQ(gl_after_max, gl_warm) << what;
  }
};

}  // namespace

TEST(Soak, ManyLightsFrames) {
  const int frames = envCount("HV_SOAK_FRAMES", 300), warm = std::min(500, frames / 6);
  auto ctx = hv::createHeadlessContext();
  hv::render::Renderer renderer;
  const hv::Scene scene = hv::loadScene(std::string(HV_SAMPLES_DIR) + "/many_lights.json");
  renderer.setScene(scene);
  Track track;
  for (int f = 1; f <= frames; ++f) {
    renderer.render(160, 90);
    track.sample(f > warm);
    if (f % std::max(1, frames / 10) == 0) {
      std::printf("[ soak ] frame %d: heap in use %.1f MB, RSS %.1f MB, live GL objects %d\n", f,
                  heapInUseMb(), rssMb(), hv::gl::liveCountTotal());
    }
  }
  track.expectFlat("many_lights frames", frames >= 1000 ? 0.0 : 4.0);
}

TEST(Soak, GltfReloads) {
  const fs::path helmet =
      hv::test::assetsDir() / "gltf" / "DamagedHelmet" / "glTF-Binary" / "DamagedHelmet.glb";
  if (hv::test::assetsDir().empty() || !fs::exists(helmet)) {
    GTEST_SKIP() << "no DamagedHelmet in the shared assets at " << helmet;
  }
  const int reloads = envCount("HV_SOAK_RELOADS", 6), warm = std::min(20, reloads / 2);
  ::setenv("HV_ASSETS_DIR", hv::test::assetsDir().c_str(), 1);
  auto ctx = hv::createHeadlessContext();
  hv::render::Renderer renderer;
  hv::app::SceneReloader reloader(std::string(HV_SAMPLES_DIR) + "/gltf.json");
  reloader.attach(renderer);
  renderer.render(64, 64);
  Track track;
  for (int i = 1; i <= reloads; ++i) {
    ASSERT_TRUE(reloader.reload()) << reloader.error();
    renderer.render(64, 64);
    track.sample(i > warm);
    std::printf("[ soak ] reload %d: heap in use %.1f MB, RSS %.1f MB, live GL objects %d\n", i,
                heapInUseMb(), rssMb(), hv::gl::liveCountTotal());
  }
  // llvmpipe frees a replaced scene's textures when the draw that last used them is recycled, at
  // a run-dependent later frame: a sample holds 0 or 1 replaced scene's textures (seen: 204 or
  // 313 MB, run to run, never more). A leak of one scene per reload still exceeds the bound.
  double texture_mb = 0;
  for (const hv::ImageData& image : reloader.scene().images) {
    texture_mb += double(image.rgba.size()) * 4.0 / 3.0 / (1024.0 * 1024.0);  // with mips
  }
  std::printf("[ soak ] one scene's textures with mips: %.1f MB\n", texture_mb);
  track.expectFlat("gltf reloads", reloads >= 100 ? 0.0 : 4.0, texture_mb);
}

// Soak (issue 18): many frames of many_lights in one process, and many hot reloads of the glTF
// sample through the viewer's SceneReloader, recording resident memory and live GL objects.
// Nothing may grow once warmed up: live GL objects constant, RSS within 2% (+ 4 MB of allocator
// slack for the short runs). The suite runs short versions; scripts/soak.sh runs the issue's
// counts (HV_SOAK_FRAMES=3000, HV_SOAK_RELOADS=300) and the viewer itself under Xvfb.
#include <gtest/gtest.h>

#include <unistd.h>

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

// RSS after warm-up vs at the end: flat within 2% (+ `slack_mb`), and the same live GL objects.
void expectFlat(const char* what, double rss_warm, double rss_end, int gl_warm, int gl_end,
                double slack_mb) {
  std::printf("[ soak ] %s: RSS %.1f -> %.1f MB (%+.2f%%), live GL objects %d -> %d\n", what,
              rss_warm, rss_end, 100.0 * (rss_end / rss_warm - 1.0), gl_warm, gl_end);
  EXPECT_LE(rss_end, rss_warm * 1.02 + slack_mb) << what;
  EXPECT_EQ(gl_end, gl_warm) << what;
}

}  // namespace

TEST(Soak, ManyLightsFrames) {
  const int frames = envCount("HV_SOAK_FRAMES", 300), warm = frames / 6;
  auto ctx = hv::createHeadlessContext();
  hv::render::Renderer renderer;
  const hv::Scene scene = hv::loadScene(std::string(HV_SAMPLES_DIR) + "/many_lights.json");
  renderer.setScene(scene);
  double rss_warm = 0;
  int gl_warm = 0;
  for (int f = 1; f <= frames; ++f) {
    renderer.render(160, 90);
    if (f == warm) rss_warm = rssMb(), gl_warm = hv::gl::liveCountTotal();
    if (f % std::max(1, frames / 10) == 0) {
      std::printf("[ soak ] frame %d: RSS %.1f MB, live GL objects %d\n", f, rssMb(),
                  hv::gl::liveCountTotal());
    }
  }
  expectFlat("many_lights frames", rss_warm, rssMb(), gl_warm, hv::gl::liveCountTotal(),
             frames >= 1000 ? 0.0 : 4.0);
}

TEST(Soak, GltfReloads) {
  const fs::path helmet =
      hv::test::assetsDir() / "gltf" / "DamagedHelmet" / "glTF-Binary" / "DamagedHelmet.glb";
  if (hv::test::assetsDir().empty() || !fs::exists(helmet)) {
    GTEST_SKIP() << "no DamagedHelmet in the shared assets at " << helmet;
  }
  const int reloads = envCount("HV_SOAK_RELOADS", 8), warm = std::min(20, reloads / 2);
  ::setenv("HV_ASSETS_DIR", hv::test::assetsDir().c_str(), 1);
  auto ctx = hv::createHeadlessContext();
  hv::render::Renderer renderer;
  hv::app::SceneReloader reloader(std::string(HV_SAMPLES_DIR) + "/gltf.json");
  reloader.attach(renderer);
  renderer.render(64, 64);
  double rss_warm = 0;
  int gl_warm = 0;
  for (int i = 1; i <= reloads; ++i) {
    ASSERT_TRUE(reloader.reload()) << reloader.error();
    renderer.render(64, 64);
    if (i == warm) rss_warm = rssMb(), gl_warm = hv::gl::liveCountTotal();
    std::printf("[ soak ] reload %d: RSS %.1f MB, live GL objects %d\n", i, rssMb(),
                hv::gl::liveCountTotal());
  }
  expectFlat("gltf reloads", rss_warm, rssMb(), gl_warm, hv::gl::liveCountTotal(),
             reloads >= 100 ? 0.0 : 4.0);
}

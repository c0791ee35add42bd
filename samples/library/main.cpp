// halfvec as a library: load a scene, render it headless, write the tone-mapped image.
//   halfvec_library_example SCENE.json OUT.png [WIDTHxHEIGHT]
// Built against an installed halfvec package (samples/library/CMakeLists.txt); docs/library.md
// walks through it.
#include <cstdio>
#include <exception>
#include <string>

#include "halfvec/image/image.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene_loader.hpp"

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: %s SCENE.json OUT.png [WIDTHxHEIGHT]\n", argv[0]);
    return 2;
  }
  try {
    // A headless OpenGL 4.5 context (EGL); the renderer draws into whatever context is current.
    std::unique_ptr<hv::Context> context = hv::createHeadlessContext();
    // The scene file: camera, objects, materials, lights, environment, settings. Throws
    // hv::SceneError naming the file and the field on bad input.
    hv::Scene scene = hv::loadScene(argv[1]);
    int width = scene.settings.width, height = scene.settings.height;
    if (argc == 4 && std::sscanf(argv[3], "%dx%d", &width, &height) != 2) {
      std::fprintf(stderr, "bad size '%s', expected WIDTHxHEIGHT\n", argv[3]);
      return 2;
    }
    hv::render::Renderer renderer;
    renderer.setScene(scene);  // uploads geometry, materials, lights; bakes the environment
    const hv::render::FrameStats stats = renderer.render(width, height);
    hv::writePng(argv[2], renderer.readLdr());
    std::printf("%s: %dx%d, %.1f ms on %s\n", argv[2], width, height, stats.total_ms,
                context->renderer().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

#include "app/scene_reload.hpp"

#include <cstdio>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <stdexcept>

#include "halfvec/gl/objects.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

namespace {

std::filesystem::file_time_type mtimeOf(const std::string& path) {
  std::error_code ec;
  auto t = std::filesystem::last_write_time(path, ec);
  return ec ? std::filesystem::file_time_type{} : t;
}

bool sameCamera(const Camera& a, const Camera& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.fov_y_deg == b.fov_y_deg && a.near_plane == b.near_plane && a.far_plane == b.far_plane;
}

// A reload frees the previous scene's images and meshes, and the GL driver its textures (tens of
// MB in a few large blocks, llvmpipe's some frames later), after the next ones were allocated
// beside them. glibc keeps such freed blocks in its heaps: its mmap threshold rises to the size
// of the largest mmapped block freed (up to 32 MB), after which blocks that size come from the
// heap and stay there. The process grew from 427 to 694 MB over the first reloads so
// (docs/hostile-input.md, "Soak"). A fixed threshold keeps large blocks mmapped, returned to the
// system when freed; malloc_trim returns what the small ones leave free.
void keepLargeBlocksMapped() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
}

void releaseFreedMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace

SceneReloader::SceneReloader(std::string path, SceneOpenOptions options)
    : path_(std::move(path)), options_(std::move(options)) {
  keepLargeBlocksMapped();
  file_time_ = mtimeOf(path_);
  scene_ = std::make_unique<Scene>(openScene(path_, options_));
  loaded_camera_ = scene_->camera;
}

void SceneReloader::attach(render::Renderer& renderer) {
  renderer.setScene(*scene_);
  renderer_ = &renderer;
}

bool SceneReloader::poll() {
  const auto t = mtimeOf(path_);
  if (t == file_time_) return false;
  file_time_ = t;
  return reload();
}

bool SceneReloader::reload() {
  if (!renderer_) throw std::logic_error("SceneReloader::reload before attach");
  try {
    auto fresh = std::make_unique<Scene>(openScene(path_, options_));
    const bool camera_edited = !sameCamera(fresh->camera, loaded_camera_);
    if (!camera_edited) fresh->camera = scene_->camera;  // keep the user's view
    try {
      renderer_->setScene(*fresh);
    } catch (...) {
      renderer_->setScene(*scene_);  // the old scene was uploaded before: this cannot half-fail
      throw;
    }
    loaded_camera_ = fresh->camera;
    scene_ = std::move(fresh);  // frees the previous scene
    releaseFreedMemory();
    error_.clear();
    std::printf("reloaded %s (live GL objects: %d)\n", path_.c_str(), gl::liveCountTotal());
    std::fflush(stdout);
    return true;
  } catch (const std::exception& e) {
    error_ = e.what();
    std::fprintf(stderr, "reload failed: %s\n", e.what());
    return false;
  }
}

}  // namespace hv::app

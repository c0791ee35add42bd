#include "app/scene_reload.hpp"

#include <cstdio>
#include <stdexcept>

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

}  // namespace

SceneReloader::SceneReloader(std::string path, SceneOpenOptions options)
    : path_(std::move(path)), options_(std::move(options)) {
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
    scene_ = std::move(fresh);
    error_.clear();
    std::printf("reloaded %s\n", path_.c_str());
    return true;
  } catch (const std::exception& e) {
    error_ = e.what();
    std::fprintf(stderr, "reload failed: %s\n", e.what());
    return false;
  }
}

}  // namespace hv::app

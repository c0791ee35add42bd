// Hot reload of a scene file for the viewer: when the file changes on disk it is loaded and
// uploaded; on any error (bad JSON, a bad field, a missing HDR or glTF, a failed environment bake)
// the last good scene stays loaded and rendering, and the error is kept for the panel.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/model_scene.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::app {

class SceneReloader {
 public:
  // Loads `path`, a scene file or a glTF model, with `options` (openScene; throws SceneError like
  // loadScene on a bad first load); needs no GL context, so a bad file fails before any window
  // opens.
  explicit SceneReloader(std::string path, SceneOpenOptions options = {});
  // Uploads the scene to `renderer` (throws like setScene), which then receives every reload and
  // must outlive this object.
  void attach(render::Renderer& renderer);

  // Reloads when the file's modification time changed since the last attempt. Returns true when
  // a new scene was loaded; on failure returns false, keeps the last good scene and sets error().
  // The user's camera is kept unless the file's camera changed.
  bool poll();
  // Reloads now, whatever the modification time.
  bool reload();

  Scene& scene() { return *scene_; }
  const std::string& error() const { return error_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  SceneOpenOptions options_;
  render::Renderer* renderer_ = nullptr;
  std::unique_ptr<Scene> scene_;
  Camera loaded_camera_;
  std::filesystem::file_time_type file_time_{};
  std::string error_;
};

}  // namespace hv::app

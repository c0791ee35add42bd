// Hot reload of a scene file for the viewer: when the file changes on disk it is loaded and
// uploaded; on any error (bad JSON, a bad field, a missing HDR or glTF, a failed environment bake)
// the last good scene stays loaded and rendering, and the error is kept for the panel.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace hv::app {

class SceneReloader {
 public:
  // Loads `path` (throws SceneError/IblError like loadScene/setScene on a bad first load) and
  // uploads it to `renderer`, which must outlive this object.
  SceneReloader(std::string path, render::Renderer& renderer);

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
  render::Renderer& renderer_;
  std::unique_ptr<Scene> scene_;
  Camera loaded_camera_;
  std::filesystem::file_time_type file_time_{};
  std::string error_;
};

}  // namespace hv::app

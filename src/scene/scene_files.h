// The files a scene reads besides its own text (meshes, images, lens files, spectra): one
// place that resolves a file name against the scene's directory, and a log of every file so
// resolved while a scene is built, so that a resumed render can refuse a scene whose
// textures or meshes changed since its state was written (render/render_state.h).
#pragma once
#include <string>
#include <vector>

namespace eyetrace {

// `name` relative to `search_dir` (unless absolute or search_dir is empty), as a path string.
// Records the result in the active SceneFileLog of this thread, if there is one.
std::string resolve_scene_file(const std::string& search_dir, const std::string& name);

// While alive, collects the paths resolve_scene_file() returns on this thread (scene building
// is single-threaded). Logs nest: the innermost one collects.
class SceneFileLog {
 public:
  SceneFileLog();
  ~SceneFileLog();
  SceneFileLog(const SceneFileLog&) = delete;
  SceneFileLog& operator=(const SceneFileLog&) = delete;
  void add(const std::string& path);
  // Sorted, without duplicates.
  std::vector<std::string> files() const;

 private:
  std::vector<std::string> files_;
  SceneFileLog* outer_;
};

}  // namespace eyetrace

#include "scene/scene_files.h"

#include <algorithm>
#include <filesystem>

namespace eyetrace {

namespace {
thread_local SceneFileLog* t_active_log = nullptr;
}  // namespace

std::string resolve_scene_file(const std::string& search_dir, const std::string& name) {
  std::filesystem::path path(name);
  if (path.is_relative() && !search_dir.empty() && !name.empty()) path = std::filesystem::path(search_dir) / path;
  std::string resolved = path.string();
  if (t_active_log && !resolved.empty()) t_active_log->add(resolved);
  return resolved;
}

SceneFileLog::SceneFileLog() : outer_(t_active_log) { t_active_log = this; }
SceneFileLog::~SceneFileLog() { t_active_log = outer_; }

void SceneFileLog::add(const std::string& path) { files_.push_back(path); }

std::vector<std::string> SceneFileLog::files() const {
  std::vector<std::string> out = files_;
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace eyetrace

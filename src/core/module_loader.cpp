#include "core/module_loader.h"

#include <dlfcn.h>
#include <fmt/core.h>
#include <link.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#ifndef EYETRACE_MODULE_BUILD_DIR
#define EYETRACE_MODULE_BUILD_DIR ""
#endif

namespace eyetrace {

namespace {

namespace fs = std::filesystem;

// The directory of the binary that contains this function.
fs::path own_directory() {
  Dl_info info{};
  link_map* map = nullptr;
  if (!dladdr1(reinterpret_cast<void*>(&own_directory), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) ||
      !map || !map->l_name)
    return {};
  // The main program's link map entry has no name (dladdr then reports argv[0], a bare name when
  // the program was found through PATH): its file is /proc/self/exe.
  fs::path file = map->l_name[0] ? fs::path(map->l_name) : fs::path("/proc/self/exe");
  std::error_code ec;
  fs::path p = fs::canonical(file, ec);
  return ec ? fs::path() : p.parent_path();
}

std::vector<fs::path> candidates(const ModuleSpec& spec) {
  if (const char* dir = std::getenv(spec.dir_variable)) return {fs::path(dir) / spec.file_name};
  std::vector<fs::path> c;
  fs::path own = own_directory();
  if (!own.empty()) {
    c.push_back(own.parent_path() / "lib" / spec.file_name);
    c.push_back(own / spec.file_name);
  }
  if (*EYETRACE_MODULE_BUILD_DIR) c.push_back(fs::path(EYETRACE_MODULE_BUILD_DIR) / spec.file_name);
  return c;
}

}  // namespace

LoadedModule load_module(const ModuleSpec& spec, const std::function<std::string(void*)>& check) {
  LoadedModule l;
  for (const fs::path& path : candidates(spec)) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      l.failure += fmt::format("\n  {}: not found", path.string());
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | (spec.global ? RTLD_GLOBAL : RTLD_LOCAL));
    if (!handle) {
      const char* why = dlerror();
      l.failure += fmt::format("\n  {}: {}", path.string(), why ? why : "dlopen failed");
      continue;
    }
    // Never dlclose one that is refused: nothing of it is in use, but unloading is not worth the risk.
    void* entry = dlsym(handle, spec.entry);
    if (!entry) {
      l.failure += fmt::format("\n  {}: no {} in it", path.string(), spec.entry);
      continue;
    }
    if (const std::string why = check ? check(entry) : std::string(); !why.empty()) {
      l.failure += fmt::format("\n  {}: {}", path.string(), why);
      continue;
    }
    l.entry = entry;
    l.failure.clear();
    return l;
  }
  if (l.failure.empty()) l.failure = "\n  (no place to look)";
  return l;
}

}  // namespace eyetrace

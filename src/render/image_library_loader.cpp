#include "render/image_library_loader.h"

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

#include "core/error.h"

#ifndef EYETRACE_IMAGE_MODULE_BUILD_DIR
#define EYETRACE_IMAGE_MODULE_BUILD_DIR ""
#endif

namespace eyetrace {

const char* const kImageModuleName = "libeyetrace_oiio.so";

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

std::vector<fs::path> candidates() {
  if (const char* dir = std::getenv("EYETRACE_IMAGE_MODULE_DIR")) return {fs::path(dir) / kImageModuleName};
  std::vector<fs::path> c;
  fs::path own = own_directory();
  if (!own.empty()) {
    c.push_back(own.parent_path() / "lib" / kImageModuleName);
    c.push_back(own / kImageModuleName);
  }
  if (*EYETRACE_IMAGE_MODULE_BUILD_DIR) c.push_back(fs::path(EYETRACE_IMAGE_MODULE_BUILD_DIR) / kImageModuleName);
  return c;
}

struct Loaded {
  ImageLibrary* library = nullptr;
  std::string failure;  // every place tried, with dlopen's reason
};

Loaded load() {
  Loaded l;
  for (const fs::path& path : candidates()) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      l.failure += fmt::format("\n  {}: not found", path.string());
      continue;
    }
    // RTLD_NOW: a missing dependency of OpenImageIO shows here, not as a crash at first use.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      l.failure += fmt::format("\n  {}: {}", path.string(), why ? why : "dlopen failed");
      continue;
    }
    auto entry = reinterpret_cast<ImageLibrary* (*)()>(dlsym(handle, EYETRACE_IMAGE_LIBRARY_ENTRY));
    ImageLibrary* lib = entry ? entry() : nullptr;
    if (!lib) {
      l.failure += fmt::format("\n  {}: no {} in it", path.string(), EYETRACE_IMAGE_LIBRARY_ENTRY);
      continue;  // never dlclose: nothing of it is in use, but unloading is not worth the risk
    }
    l.library = lib;
    l.failure.clear();
    return l;
  }
  if (l.failure.empty()) l.failure = "\n  (no place to look)";
  return l;
}

}  // namespace

ImageLibrary& image_library(const std::string& file) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.library)
    throw_error(
        fmt::format("image \"{}\": needs OpenImageIO, but eyetrace's OpenImageIO module {} cannot be loaded "
                    "(set EYETRACE_IMAGE_MODULE_DIR to the directory holding it):{}",
                    file, kImageModuleName, loaded.failure));
  return *loaded.library;
}

}  // namespace eyetrace

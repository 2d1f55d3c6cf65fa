#include "render/image_library_loader.h"

#include <mutex>

#include "core/error.h"
#include "core/module_loader.h"

namespace eyetrace {

const char* const kImageModuleName = "libeyetrace_oiio.so";

namespace {

struct Loaded {
  ImageLibrary* library = nullptr;
  std::string failure;  // every place tried, with dlopen's reason
};

Loaded load() {
  ImageLibrary* library = nullptr;
  const LoadedModule m =
      load_module({kImageModuleName, "EYETRACE_IMAGE_MODULE_DIR", EYETRACE_IMAGE_LIBRARY_ENTRY}, [&](void* entry) {
        library = reinterpret_cast<ImageLibrary* (*)()>(entry)();
        return library ? std::string() : fmt::format("{} gave no library", EYETRACE_IMAGE_LIBRARY_ENTRY);
      });
  return {m.entry ? library : nullptr, m.failure};
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

// Finds and loads the OpenImageIO module (render/image_library.h) the first time it is needed,
// where core/module_loader.h looks, the environment variable being EYETRACE_IMAGE_MODULE_DIR.
// The module is never unloaded.
#pragma once
#include <string>

#include "render/image_library.h"

namespace eyetrace {

// The module's library. Throws SceneError naming `file` (the image that needs it) and every
// place tried with dlopen's reason when it cannot be loaded.
ImageLibrary& image_library(const std::string& file);

// The module's file name (libeyetrace_oiio.so).
extern const char* const kImageModuleName;

}  // namespace eyetrace

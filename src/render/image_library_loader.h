// Finds and loads the OpenImageIO module (render/image_library.h) the first time it is needed.
//
// Where: the directory named by the environment variable EYETRACE_IMAGE_MODULE_DIR when it is
// set (and only there); else next to the binary holding this code (the eyetrace executable, a
// test binary, the Python module): its ../lib, then its own directory; then the build tree's lib
// directory, fixed at compile time. The module is never unloaded.
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

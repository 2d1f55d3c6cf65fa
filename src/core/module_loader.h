// Finds and loads one of eyetrace's own modules: shared objects built into build/lib and opened
// with dlopen only when a run needs them, so that a run that does not maps none of their
// libraries (the OpenImageIO module, render/image_library_loader.h; the MPI module,
// distributed/mpi_module_loader.h).
//
// Where: the directory named by the module's environment variable when it is set (and only
// there); else next to the binary holding this code (the eyetrace executable, a test binary, the
// Python module): its ../lib, then its own directory; then the build tree's lib directory, fixed
// at compile time. A module is never unloaded.
#pragma once
#include <functional>
#include <string>

namespace eyetrace {

struct ModuleSpec {
  const char* file_name;     // "libeyetrace_oiio.so"
  const char* dir_variable;  // the environment variable naming the one directory to look in
  const char* entry;         // the module's one exported symbol
  // Whether the module's own libraries are opened for all later loads to see (RTLD_GLOBAL):
  // libraries that dlopen plugins of their own which expect to find their symbols need it.
  bool global = false;
};

struct LoadedModule {
  void* entry = nullptr;  // the entry point's address; null when no place gave a usable module
  std::string failure;    // when null: every place tried, one "\n  path: reason" line each
};

// Tries the places in order and returns the first module that opens (RTLD_NOW: a missing
// dependency shows here, not at first use), has the entry point and passes `check` (given the
// entry point; it returns "" or why the module cannot be used, e.g. another build's interface).
LoadedModule load_module(const ModuleSpec& spec, const std::function<std::string(void*)>& check = {});

}  // namespace eyetrace

#include "distributed/mpi_module_loader.h"

#include <mutex>
#include <string>

#include "core/error.h"
#include "core/module_loader.h"

namespace eyetrace {

const char* const kMpiModuleName = "libeyetrace_mpi.so";

namespace {

struct Loaded {
  const MpiModule* module = nullptr;
  std::string failure;  // every place tried, with the reason
};

Loaded load() {
  const MpiModule* module = nullptr;
  // RTLD_GLOBAL, as mpi4py opens libmpi: MPI libraries dlopen components of their own (Open
  // MPI's mca_*.so, which do not all link libopen-pal) that may expect its symbols to be global.
  // (Debian 12's Open MPI 4.1 also works with RTLD_LOCAL; the module's own symbols are hidden.)
  const LoadedModule m =
      load_module({kMpiModuleName, "EYETRACE_MPI_MODULE_DIR", EYETRACE_MPI_MODULE_ENTRY, true}, [&](void* entry) {
        module = reinterpret_cast<const MpiModule* (*)()>(entry)();
        if (!module) return fmt::format("{} gave nothing", EYETRACE_MPI_MODULE_ENTRY);
        if (module->version != kMpiModuleVersion)
          return fmt::format("interface version {}, this eyetrace needs {} (a module of another build)",
                             module->version, kMpiModuleVersion);
        return std::string();
      });
  return {m.entry ? module : nullptr, m.failure};
}

}  // namespace

const MpiModule& mpi_module(const char* what) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.module)
    throw_error(
        fmt::format("eyetrace {} was started by an MPI launcher (mpirun, srun) and needs MPI, but eyetrace's "
                    "MPI module {} cannot be loaded (set EYETRACE_MPI_MODULE_DIR to the directory holding it):{}",
                    what, kMpiModuleName, loaded.failure));
  return *loaded.module;
}

}  // namespace eyetrace

#include <cstdio>
#include <new>

#include "app/commands.h"
#include "core/error.h"

namespace eyetrace {

int report_error(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const SceneError& e) {
    // One line per diagnostic, compiler style, then how many when there are several.
    for (const Diagnostic& d : e.diagnostics()) std::fprintf(stderr, "%s\n", d.to_string().c_str());
    if (e.diagnostics().size() > 1) std::fprintf(stderr, "%zu errors\n", e.diagnostics().size());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  }
  return 1;
}

}  // namespace eyetrace

// eyetrace.Error: every error eyetrace reports (scene errors with file:line:col, optics errors
// naming the eye option, unreadable files) as one Python exception whose message is the text
// the command line prints, so that a script can show it or match it, and the interpreter goes on.
#include <fmt/core.h>

#include <new>
#include <string>

#include "core/error.h"
#include "optics/optics_error.h"
#include "python/bindings.h"

namespace py = pybind11;

namespace eyetrace::python {

namespace {

// The command line's stderr text of a SceneError (main.cpp): one line per diagnostic, then the
// count when there are several.
std::string scene_error_text(const SceneError& e) {
  std::string text;
  for (const Diagnostic& d : e.diagnostics()) text += (text.empty() ? "" : "\n") + d.to_string();
  if (e.diagnostics().size() > 1) text += fmt::format("\n{} errors", e.diagnostics().size());
  return text;
}

// Raises `type(text)` with the attribute `diagnostics`: a list of dicts (file, line, column,
// parameter, message), one per diagnostic, for scripts that want the fields and not the text.
void raise(PyObject* type, const std::string& text, const py::list& diagnostics) {
  py::object error = py::reinterpret_borrow<py::object>(type)(text);
  error.attr("diagnostics") = diagnostics;
  PyErr_SetObject(type, error.ptr());
}

py::dict diagnostic_dict(const Diagnostic& d) {
  py::dict r;
  r["file"] = d.loc.file;
  r["line"] = d.loc.line;
  r["column"] = d.loc.column;
  r["parameter"] = d.parameter;
  r["message"] = d.message;
  return r;
}

}  // namespace

void bind_errors(py::module_& m) {
  // Kept for the module's lifetime (the translator refers to it): a leaked reference, as
  // pybind11's own register_exception does.
  static PyObject* error_type = PyErr_NewExceptionWithDoc(
      "eyetrace.Error",
      "An eyetrace error: the message is the text the command line prints (file:line:col: error: ...); "
      "`diagnostics` lists each one's file, line, column, parameter and message.",
      PyExc_Exception, nullptr);
  m.add_object("Error", py::handle(error_type));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const py::error_already_set&) {
      throw;  // a Python exception (KeyboardInterrupt, ...) passes through as it is
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const SceneError& e) {
      py::list ds;
      for (const Diagnostic& d : e.diagnostics()) ds.append(diagnostic_dict(d));
      raise(error_type, scene_error_text(e), ds);
    } catch (const optics::OpticsError& e) {
      Diagnostic d;
      d.parameter = e.option();
      d.message = e.message();
      raise(error_type, fmt::format("error: {}", e.what()), py::list(py::make_tuple(diagnostic_dict(d))));
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "error: out of memory");
    } catch (const std::exception& e) {
      // As the command line prints any other failure (main.cpp).
      Diagnostic d;
      d.message = e.what();
      raise(error_type, fmt::format("error: {}", e.what()), py::list(py::make_tuple(diagnostic_dict(d))));
    }
  });
}

}  // namespace eyetrace::python

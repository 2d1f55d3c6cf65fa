// The parts of the Python module `eyetrace` (docs/python.md), each adding its names to the
// module: the exception class, the Eye (optics), and render().
#pragma once
#include <pybind11/pybind11.h>

namespace eyetrace::python {

// eyetrace.Error (derived from Exception) and the translation of every eyetrace error into it.
void bind_errors(pybind11::module_& m);
// eyetrace.Eye: an eye from a model name and camera parameters, a Camera directive or a
// prescription file, and its optics report, spots, wavefront, PSF and MTF.
void bind_eye(pybind11::module_& m);
// eyetrace.render(): a scene file or scene text to a numpy array.
void bind_render(pybind11::module_& m);

}  // namespace eyetrace::python

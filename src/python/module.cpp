// The Python module `eyetrace`: the optics library and the renderer from Python (docs/python.md).
#include "python/bindings.h"

PYBIND11_MODULE(eyetrace, m) {
  m.doc() =
      "eyetrace: schematic human eyes (optics reports, spots, wavefront, PSF, MTF) and physically based renders "
      "through them. Errors raise eyetrace.Error with the command line's message.";
  eyetrace::python::bind_errors(m);
  eyetrace::python::bind_eye(m);
  eyetrace::python::bind_render(m);
}

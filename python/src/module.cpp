// The extension module dlfl._dlfl, which the package dlfl (python/dlfl/__init__.py) re-exports.

#include "binding.h"

PYBIND11_MODULE(_dlfl, m) {
  m.doc() = "The compiled part of dlfl; use the package dlfl, which re-exports it.";
  m.attr("__version__") = DLFL_VERSION;
  dlfl::python::bind_errors(m);
  dlfl::python::bind_mesh(m);
  dlfl::python::bind_io(m);
  dlfl::python::bind_schemes(m);
  dlfl::python::bind_editor(m);
  dlfl::python::bind_render(m);
}

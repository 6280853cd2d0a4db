// Subdivision: every registered scheme by name (through the registered operation "subdivide", as the editor
// and the logs run it), the scheme listing, and MLCA on cell complexes. The GIL is released while a scheme
// runs.

#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/spec_json.h>
#include <dlfl/schemes/scheme_registry.h>
#include "binding.h"

namespace dlfl::python {

Params subdivide_params(const std::string& scheme, std::int64_t iterations, const py::kwargs& params) {
  const SchemeSpec& spec = find_scheme(scheme);
  return {{"scheme", spec.name},
          {"iterations", iterations},
          {"params", to_params(spec.name, spec.params, py::args(), params)}};
}

void bind_schemes(py::module_& m) {
  m.def(
      "subdivide",
      [](const MeshRef& mesh, const std::string& scheme, std::int64_t iterations, const py::kwargs& params) {
        const Params given = subdivide_params(scheme, iterations, params);
        const OperationSpec& op = find_operation("subdivide");
        return MeshRef(mesh.read_without_gil([&](const Mesh& input) {
          return op.replace(input, resolve_operation_params(op, given, input));
        }));
      },
      R"doc(The mesh after `iterations` steps of the named scheme (dlfl.schemes() lists them), the scheme's
parameters as keywords: subdivide(mesh, "honeycomb", iterations=2, t=0.5). Parameters are checked (and
defaulted) before any work; a bad one raises ParameterError naming it ("params.t"), an unknown scheme
ParameterError naming "scheme" with a suggestion. The input is not changed. The GIL is released meanwhile.)doc",
      py::arg("mesh"), py::arg("scheme"), py::arg("iterations") = 1);
  m.def(
      "schemes", [] { return from_json(schemes_json()); },
      "Every registered scheme: a list of {'name', 'doc', 'params': [{'name', 'type', 'default', 'range', "
      "'keywords', 'doc', 'optional', ...}]}, as `dlfl schemes --json` prints it.");
  m.def(
      "operations", [] { return from_json(operations_json()); },
      "Every registered operation: a list of {'name', 'kind', 'doc', 'counts', 'params'}, as `dlfl ops "
      "--json` "
      "prints it. Each is also a method of Editor.");
  m.def(
      "mlca_subdivide",
      [](const ComplexRef& complex, int iterations) {
        py::gil_scoped_release no_gil;
        return ComplexRef{std::make_shared<const CellComplex>(mlca_subdivide(*complex.complex, iterations))};
      },
      "`iterations` steps of MLCA subdivision (multi-linear cell averaging) of a cell complex: curves, quad "
      "surfaces and hexahedral volumes, lower-dimensional cells as creases. Input vertex i stays vertex i. "
      "The GIL is released meanwhile.",
      py::arg("complex"), py::arg("iterations") = 1);
}

}  // namespace dlfl::python

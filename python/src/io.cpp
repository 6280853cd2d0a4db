// Files: meshes (OBJ, OFF, PLY, the native JSON) and cell complexes (VTK, OBJ), with the dlfl.CellComplex
// class. The GIL is released while a file is read or written.

#include <cstring>

#include <dlfl/cells/cell_info.h>
#include <dlfl/cells/cell_io.h>
#include <dlfl/io/mesh_io.h>
#include "binding.h"

namespace dlfl::python {
namespace {

py::object complex_owner(const ComplexRef& self) {
  auto* keep = new std::shared_ptr<const CellComplex>(self.complex);
  return py::capsule(keep, [](void* p) { delete static_cast<std::shared_ptr<const CellComplex>*>(p); });
}

void bind_cell_complex(py::module_& m) {
  py::class_<ComplexRef> c(m, "CellComplex",
                           R"doc(A complex of d-cubes (d = 0..3) of mixed dimensions, the mesh type of MLCA
subdivision: cell i is indices[offsets[i]:offsets[i + 1]], 1, 2, 4 or 8 vertex indices in tensor-product
order (a quad cycle a b c d is the cell (a, b, d, c)). It never changes once made: its arrays are read-only
views.)doc");
  c.def_static(
      "from_arrays",
      [](py::handle positions, py::handle cells) {
        CellComplex complex;
        read_indexed_lists(complex, positions, cells, "CellComplex.from_arrays",
                           [](std::size_t i, const std::string& why) {
                             throw InvalidArgument("cell complex: cell " + std::to_string(i) + ": " + why);
                           });
        check_cell_complex(complex);
        return ComplexRef{std::make_shared<const CellComplex>(std::move(complex))};
      },
      "A cell complex from positions, an (n, 3) array, and cells: a list of index lists, an (m, k) integer "
      "array, or a tuple (offsets, indices). Raises InvalidArgument naming the first bad cell or vertex.",
      py::arg("positions"), py::arg("cells"));
  c.def_property_readonly(
      "positions",
      [](const ComplexRef& self) {
        return point_view(self.complex->positions.data(), self.complex->positions.size(),
                          complex_owner(self));
      },
      "The vertex positions, an (n, 3) float64 read-only view.");
  c.def_property_readonly(
      "offsets",
      [](const ComplexRef& self) {
        return index_view(self.complex->offsets.data(), self.complex->offsets.size(), complex_owner(self));
      },
      "Where each cell starts in indices (one more than the cells), uint32, a read-only view.");
  c.def_property_readonly(
      "indices",
      [](const ComplexRef& self) {
        return index_view(self.complex->indices.data(), self.complex->indices.size(), complex_owner(self));
      },
      "The cells' vertex indices, uint32, a read-only view.");
  c.def_property_readonly(
      "num_vertices", [](const ComplexRef& self) { return self.complex->positions.size(); }, "Vertices.");
  c.def_property_readonly(
      "num_cells", [](const ComplexRef& self) { return self.complex->num_cells(); },
      "Cells of every dimension.");
  c.def(
      "dimensions",
      [](const ComplexRef& self) {
        py::array_t<std::int8_t> out(py::ssize_t(self.complex->num_cells()));
        for (std::size_t i = 0; i < self.complex->num_cells(); ++i) {
          out.mutable_at(py::ssize_t(i)) = std::int8_t(self.complex->dimension(i));
        }
        return out;
      },
      "The dimension of each cell (0 to 3), int8.");
  c.def("__repr__", [](const ComplexRef& self) {
    return "<dlfl.CellComplex " + std::to_string(self.complex->positions.size()) + " vertices, " +
           std::to_string(self.complex->num_cells()) + " cells>";
  });

  m.def(
      "read_cell_complex",
      [](py::handle path) {
        const std::string p = path_text(path);
        py::gil_scoped_release no_gil;
        return ComplexRef{std::make_shared<const CellComplex>(read_cell_complex(p))};
      },
      "Reads a .vtk or .obj file as a cell complex. Raises IoError (path, line).", py::arg("path"));
  m.def(
      "write_cell_complex",
      [](const ComplexRef& complex, py::handle path, bool ascii) {
        const std::string p = path_text(path);
        py::gil_scoped_release no_gil;
        write_cell_complex(*complex.complex, p, {.binary_vtk = !ascii});
      },
      "Writes a .vtk (binary unless ascii) or .obj file atomically. Raises IoError or InvalidArgument before "
      "any file is touched.",
      py::arg("complex"), py::arg("path"), py::arg("ascii") = false);
  m.def(
      "info",
      [](const ComplexRef& complex, bool angles, bool shape) {
        if (angles) throw InvalidArgument("info: angles measure polyhedra; a cell complex has none");
        if (shape) throw InvalidArgument("info: the shape measures surfaces; a cell complex has none");
        return from_json(cell_complex_info_json(*complex.complex, -1));
      },
      "What `dlfl info` prints for a cell complex, as a dict: vertices, cells, cells_by_dimension, bbox.",
      py::arg("complex"), py::arg("angles") = false, py::arg("shape") = false);
}

}  // namespace

void bind_io(py::module_& m) {
  m.def(
      "read_mesh",
      [](py::handle path) {
        const std::string p = path_text(path);
        py::gil_scoped_release no_gil;
        return MeshRef(read_mesh(p));
      },
      "Reads a mesh file, format by extension (.obj, .off, .ply, .stl, .json; .json keeps every handle). "
      "Boundary "
      "loops become hole faces. Raises IoError (path, line).",
      py::arg("path"));
  m.def(
      "write_mesh",
      [](const MeshRef& mesh, py::handle path, bool ascii) {
        const std::string p = path_text(path);
        mesh.read_without_gil([&](const Mesh& x) {
          write_mesh(x, p, {.binary = !ascii});
          return 0;
        });
      },
      "Writes a mesh, format by extension, atomically (PLY and STL binary unless ascii; .glb too). Polygon "
      "formats leave out "
      "holes and point spheres and raise TopologyError for a 2-gon or a double edge; .json keeps everything.",
      py::arg("mesh"), py::arg("path"), py::arg("ascii") = false);
  bind_cell_complex(m);
}

}  // namespace dlfl::python

#include <dlfl/cells/cell_io.h>

#include <cctype>
#include <fstream>
#include <string>
#include <system_error>

#include <dlfl/cells/cell_obj.h>
#include <dlfl/cells/vtk.h>
#include <dlfl/errors.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/detail/text_io.h>

namespace dlfl {
namespace {

[[noreturn]] void unknown_extension(const std::filesystem::path& path) {
  throw IoError("unknown cell complex format '" + path.extension().string() + "' (use .vtk or .obj)",
                path.string());
}

}  // namespace

CellComplex read_cell_complex(const std::filesystem::path& path) {
  const std::string ext = io_detail::lower_extension(path);
  if (ext == ".vtk") return parse_vtk(io_detail::read_file(path), path.string());
  if (ext == ".obj") return parse_cell_obj(io_detail::read_file(path), path.string());
  unknown_extension(path);
}

void check_cell_complex_output(const CellComplex& complex, const std::filesystem::path& path) {
  const std::string ext = io_detail::lower_extension(path);
  if (ext != ".vtk" && ext != ".obj") unknown_extension(path);
  if (ext == ".vtk" && complex.num_cells() + complex.indices.size() > 0xFFFFFFFEu) {
    // The CELLS header counts cells plus indices; readers (ours included) take it as a 32-bit number.
    throw IoError("the complex has " + std::to_string(complex.num_cells()) + " cells with " +
                      std::to_string(complex.indices.size()) +
                      " vertex indices, more than a VTK legacy file holds",
                  path.string());
  }
  if (ext == ".obj") {
    for (std::size_t i = 0; i < complex.num_cells(); ++i) {
      if (complex.dimension(i) == 3) {
        throw IoError(
            "cell " + std::to_string(i) + " is a hexahedron, which OBJ cannot hold; write a .vtk file",
            path.string());
      }
    }
  }
}

void write_cell_complex(const CellComplex& complex, const std::filesystem::path& path,
                        const CellWriteOptions& options) {
  check_cell_complex_output(complex, path);  // before any file is touched
  check_cell_complex(complex);
  if (io_detail::lower_extension(path) == ".vtk") {
    write_atomically(
        path, [&](std::ostream& out) { write_vtk(out, complex, options.binary_vtk); }, true);
    return;
  }
  write_atomically(
      path, [&](std::ostream& out) { write_cell_obj(out, complex); }, true);
}

bool is_cell_complex_file(const std::filesystem::path& path) {
  const std::string ext = io_detail::lower_extension(path);
  if (ext == ".vtk") return true;
  if (ext != ".obj") return false;
  try {
    return obj_has_cell_statements(io_detail::read_file(path));
  } catch (const IoError&) {
    return false;
  }
}

}  // namespace dlfl

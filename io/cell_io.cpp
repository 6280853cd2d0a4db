#include "io/cell_io.h"

#include <cctype>
#include <fstream>
#include <string>
#include <system_error>

#include "dlfl/errors.h"
#include "io/atomic_file.h"
#include "io/cell_obj.h"
#include "io/io_detail.h"
#include "io/vtk.h"

namespace dlfl {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string read_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw IoError("cannot open: it is a directory", name);
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if (!in) throw IoError("cannot open: " + std::generic_category().message(errno), name);
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return io_detail::read_all(in, name, ec ? 0 : static_cast<std::size_t>(size));
}

[[noreturn]] void unknown_extension(const std::filesystem::path& path) {
  throw IoError("unknown cell complex format '" + path.extension().string() + "' (use .vtk or .obj)",
                path.string());
}

}  // namespace

CellComplex read_cell_complex(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".vtk") return parse_vtk(read_file(path), path.string());
  if (ext == ".obj") return parse_cell_obj(read_file(path), path.string());
  unknown_extension(path);
}

void write_cell_complex(const CellComplex& complex, const std::filesystem::path& path,
                        const CellWriteOptions& options) {
  const std::string ext = lower_extension(path);
  if (ext != ".vtk" && ext != ".obj") unknown_extension(path);
  check_cell_complex(complex);  // before any file is touched
  if (ext == ".vtk") {
    write_atomically(
        path, [&](std::ostream& out) { write_vtk(out, complex, options.binary_vtk); }, true);
    return;
  }
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    if (complex.dimension(i) == 3) {
      throw IoError(
          "cell " + std::to_string(i) + " is a hexahedron, which OBJ cannot hold; write a .vtk file",
          path.string());
    }
  }
  write_atomically(
      path, [&](std::ostream& out) { write_cell_obj(out, complex); }, true);
}

bool is_cell_complex_file(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".vtk") return true;
  if (ext != ".obj") return false;
  try {
    return obj_has_cell_statements(read_file(path));
  } catch (const IoError&) {
    return false;
  }
}

}  // namespace dlfl

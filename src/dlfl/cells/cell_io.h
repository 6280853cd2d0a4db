#pragma once
// Cell complexes in files, format by extension: .vtk (VTK legacy unstructured grid, dlfl/cells/vtk.h) and
// .obj (dlfl/cells/cell_obj.h). The tool asks `is_cell_complex_file` to choose between the DLFL and the
// cell-complex path.

#include <filesystem>

#include <dlfl/cells/cell_complex.h>

namespace dlfl {

struct CellWriteOptions {
  bool binary_vtk = true;  ///< .vtk only: BINARY (default, big-endian) or ASCII
};

/// Reads a .vtk or .obj file (extension case-insensitive) as a cell complex. Throws IoError naming the path
/// (and line) for another extension, an unreadable file or malformed content.
CellComplex read_cell_complex(const std::filesystem::path& path);

/// Writes a .vtk or .obj file atomically: nothing is written unless all of it is (a temporary file renamed
/// into place). Throws IoError for another extension or a hexahedron in .obj, InvalidArgument if
/// `check_cell_complex` fails; in both cases before any file is touched.
void write_cell_complex(const CellComplex& complex, const std::filesystem::path& path,
                        const CellWriteOptions& options = {});

/// Throws IoError, as `write_cell_complex` would, if `path` cannot hold `complex`: an extension other than
/// .vtk and .obj, hexahedra for .obj, or more cells and indices than a VTK legacy file counts. Subdivision
/// keeps the dimensions of the cells, so a caller can refuse before long work rather than after it.
void check_cell_complex_output(const CellComplex& complex, const std::filesystem::path& path);

/// True for a file that only the cell-complex path can read: any .vtk file, and an .obj file with `p` or `l`
/// statements (points or curves). An .obj of polygons only, any other extension, and an .obj that cannot be
/// read give false (the polygon-mesh path then reads it, or reports the error).
bool is_cell_complex_file(const std::filesystem::path& path);

}  // namespace dlfl

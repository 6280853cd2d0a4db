#pragma once
// VTK legacy unstructured grids (.vtk, ASCII and BINARY) for cell complexes, so that MLCA results open in
// ParaView. See docs/mlca_formats.md for the subset read and written.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include <dlfl/cells/cell_complex.h>

namespace dlfl {

/// VTK's vertex order of a quad (VTK_QUAD, cyclic) and a hexahedron (VTK_HEXAHEDRON: bottom cycle, then top
/// cycle) against the tensor-product order of `CellComplex`: tensor vertex k is VTK vertex `order[k]`. Both
/// permutations swap the last two vertices of each cycle and are their own inverses, so VTK vertex k is also
/// tensor vertex `order[k]`.
inline constexpr std::uint32_t vtk_quad_order[4] = {0, 1, 3, 2};
inline constexpr std::uint32_t vtk_hexahedron_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};

/// Parses a VTK legacy file held in memory (`name` is used in error messages): header "# vtk DataFile
/// Version x.y", a title line, ASCII or BINARY (big-endian), DATASET UNSTRUCTURED_GRID, then POINTS (float
/// or double), CELLS (the count-prefixed lists of versions before 5, or OFFSETS and CONNECTIVITY of version
/// 5.x) and CELL_TYPES; POINT_DATA, CELL_DATA and FIELD end the part that is read. Cell types: VERTEX (1),
/// POLY_VERTEX (2, split into vertices), LINE (3), POLY_LINE (4, split into segments), PIXEL (8), QUAD (9),
/// VOXEL (11), HEXAHEDRON (12); quads and hexahedra are mapped to tensor order, pixels and voxels already
/// are. Throws IoError with the file and (in ASCII parts) the line for a bad header, an unsupported dataset,
/// section or cell type, a wrong vertex count for a type, an index out of range, a vertex repeated in a
/// cell, a non-finite coordinate and a truncated file.
CellComplex parse_vtk(std::string_view data, const std::string& name);

/// Writes a VTK legacy file (version 3.0, readable by every VTK): POINTS as double, cells as VERTEX, LINE,
/// QUAD and HEXAHEDRON in VTK order. ASCII numbers are the shortest decimals that read back to the same
/// double (at most 17 significant digits); BINARY is big-endian doubles and 32-bit indices, as the format
/// prescribes. Either way positions round-trip bit-identically. Throws InvalidArgument if
/// `check_cell_complex` fails, IoError if the complex has more than 2^31 - 1 vertices (VTK's indices are
/// signed 32-bit).
void write_vtk(std::ostream& out, const CellComplex& complex, bool binary);

/// Reads a .vtk file (see `parse_vtk`). Throws IoError naming the path if it cannot be read.
CellComplex read_vtk(const std::filesystem::path& path);

/// Writes a .vtk file atomically (a temporary file renamed into place, so a failure leaves no partial file).
void write_vtk(const CellComplex& complex, const std::filesystem::path& path, bool binary);

}  // namespace dlfl

#pragma once
// A complex of topological d-cubes (d = 0 to 3) of mixed dimensions: the mesh type of MLCA subdivision
// (docs/mlca.md). Hexahedral volumes and non-manifold curve and surface networks are not 2-manifolds, so this
// lives beside the DLFL rather than inside it. Lower-dimensional cells mixed with higher ones are creases.

#include <cstdint>
#include <initializer_list>
#include <span>

#include <dlfl/indexed_lists.h>

namespace dlfl {

/// Positions plus cells given as vertex indices, stored flat like `PolygonSoup` (IndexedLists): cell i uses
/// `indices[offsets[i] .. offsets[i+1])`, and its size 1, 2, 4 or 8 gives its dimension 0, 1, 2 or 3.
///
/// Vertex order of a d-cube is the tensor-product order: vertex k of a cell sits at the corner of the unit
/// d-cube whose coordinates are the bits of k (bit 0 is x, bit 1 is y, bit 2 is z). So a segment is (p0, p1);
/// a quad is (p00, p10, p01, p11), whose boundary cycle is v0 v1 v3 v2; a hexahedron is (p000, p100, p010,
/// p110, p001, p101, p011, p111). The cyclic orders of file formats (VTK quads and hexahedra, OBJ faces) are
/// mapped on read and write.
struct CellComplex : IndexedLists {
  std::size_t num_cells() const { return num_lists(); }
  /// The vertex indices of cell i, in tensor-product order.
  std::span<const std::uint32_t> cell(std::size_t i) const { return list(i); }
  /// The dimension of cell i: 0 (a vertex), 1 (a segment), 2 (a quad) or 3 (a hexahedron).
  int dimension(std::size_t i) const { return dimension_of_size(offsets[i + 1] - offsets[i]); }

  /// Appends a cell of 1, 2, 4 or 8 vertex indices (tensor-product order). Throws InvalidArgument for any
  /// other size; indices are checked by `check_cell_complex`.
  void add_cell(std::span<const std::uint32_t> cell);
  void add_cell(std::initializer_list<std::uint32_t> cell) { add_cell(std::span(cell.begin(), cell.size())); }

  /// 0, 1, 2, 3 for 1, 2, 4, 8 vertices; -1 for any other count.
  static int dimension_of_size(std::size_t size) {
    return size == 1 ? 0 : size == 2 ? 1 : size == 4 ? 2 : size == 8 ? 3 : -1;
  }
};

/// Checks the whole complex and throws InvalidArgument naming the first offending cell (by index) or vertex:
/// a cell whose size is not 1, 2, 4 or 8, an index out of range, a vertex repeated within a cell, a
/// non-finite position, or offsets that do not describe `indices`. O(size).
void check_cell_complex(const CellComplex& complex);

}  // namespace dlfl

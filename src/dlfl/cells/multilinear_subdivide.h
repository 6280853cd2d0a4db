#pragma once
// Multi-linear subdivision of a cell complex (Bajaj, Schaefer, Warren, Xu, section 2.1): the splitting half
// of MLCA subdivision.

#include <dlfl/cells/cell_complex.h>

namespace dlfl {

/// Splits every d-cube into 2^d d-cubes and places each new vertex at the centroid of the coarse sub-face it
/// stands for (a coarse edge, face or hexahedron), which is where multi-linear interpolation puts it.
///
/// A new vertex is shared by every cell that contains its coarse sub-face: it is found through a hash keyed
/// by the sorted vertex set of that sub-face (the smallest coarse cell containing it), so a crease segment on
/// an edge of a quad, or a crease quad on a face of a hexahedron, gets the very same midpoint or face centre.
/// Two cells with the same vertex set share their centre. O(size).
///
/// Numbering, deterministic: input vertex i keeps index i and its position; each new vertex gets the next
/// index when first met, walking the cells in order and, within a cell, its sub-faces in the order of the
/// points of the 3^d grid of the split cell (grid point (c_0, .., c_{d-1}), c_i in {0, 1, 2}, has index
/// sum c_i 3^i; c_i = 1 means "midway along axis i"). So V' = V + (distinct edges) + (distinct faces) +
/// (distinct hexahedra). Cells: the 2^d sub-cells of each input cell are output together, in input cell
/// order; sub-cell s (bit i of s: the lower or upper half along axis i) comes s-th, and its corner k is grid
/// point s + k, so sub-cells keep the tensor-product vertex order and the orientation of their parent. A
/// 0-cell is copied as it is.
///
/// Throws InvalidArgument if the complex fails `check_cell_complex`, or if the result would not fit 32-bit
/// indices. The input is not modified.
CellComplex multilinear_subdivide(const CellComplex& complex);

namespace detail {
/// `multilinear_subdivide` without `check_cell_complex`, for callers that checked the input already.
CellComplex multilinear_subdivide_unchecked(const CellComplex& complex);
}  // namespace detail

}  // namespace dlfl

#pragma once
// Cell averaging with creases (Bajaj, Schaefer, Warren, Xu, sections 2.2 and 3.2): the smoothing half of MLCA
// subdivision.

#include <cstdint>
#include <vector>

#include <dlfl/cells/cell_complex.h>

namespace dlfl {

/// dim[v] of section 3.2 for every vertex: the lowest dimension of a cell that contains v (0 to 3), or -1 for
/// a vertex that no cell uses. Throws InvalidArgument if the complex fails `check_cell_complex`. O(size).
std::vector<std::int8_t> crease_dimensions(const CellComplex& complex);

/// Moves every vertex v to the centroid of the centroids of the cells of dimension dim[v] that contain it
/// (section 3.2). When all cells have one dimension this is plain cell averaging, formula (1); a vertex on a
/// lower-dimensional cell (a crease) only sees the cells of the crease, so a 0-cell keeps its position and a
/// vertex on a crease curve follows the curve rule. A vertex in no cell keeps its position: it has no
/// neighbourhood to average over, and keeping it makes an isolated point a fixed point of the scheme. Every
/// centroid is read from the positions before the call. Topology is untouched.
///
/// Throws InvalidArgument if the complex fails `check_cell_complex` (and leaves it unchanged). O(size).
void cell_average(CellComplex& complex);

namespace detail {
/// `cell_average` without `check_cell_complex`, for callers that checked the complex already.
void cell_average_unchecked(CellComplex& complex);
}  // namespace detail

}  // namespace dlfl

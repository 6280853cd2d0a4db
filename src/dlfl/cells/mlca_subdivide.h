#pragma once
// MLCA subdivision (multi-linear cell averaging, Bajaj, Schaefer, Warren and Xu, "A subdivision scheme for
// hexahedral meshes"): curves, quad surfaces and hexahedral volumes, with creases and non-manifold topology.
// See docs/mlca.md.

#include <dlfl/cells/cell_complex.h>

namespace dlfl {

/// `iterations` steps of MLCA subdivision: each step is `multilinear_subdivide` (every d-cube into 2^d, new
/// vertices at the centroids of coarse edges, faces and cubes) followed by `cell_average` with creases (every
/// vertex to the centroid of the centroids of the cells of dimension dim[v] that contain it).
///
/// On curves this is cubic B-spline subdivision, on quad meshes bi-cubic B-splines in regular regions (and
/// Catmull-Clark's rules except for the vertex rule at valence != 4), on hexahedral meshes tri-cubic
/// B-splines in regular regions. Lower-dimensional cells are creases: 0-cells are interpolated, vertices on a
/// curve of 1-cells follow the cubic B-spline curve rules, on a surface of 2-cells the surface rules.
/// Non-manifold configurations (n > 2 segments at a vertex, n > 2 quads at an edge) need no special case.
///
/// Vertex and cell numbering are those of `multilinear_subdivide` at each step, so input vertex i is output
/// vertex i (moved). 0 iterations return a copy. Throws InvalidArgument for a negative `iterations`, for a
/// complex that fails `check_cell_complex` (naming the cell or vertex), or if the result would not fit 32-bit
/// indices. O(size of the output).
CellComplex mlca_subdivide(const CellComplex& complex, int iterations = 1);

}  // namespace dlfl

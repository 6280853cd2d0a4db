#pragma once
// columns: the frame of wireframe built from n-sided columns along the edges and joints at the vertices
// (docs/modeling.md, "Shells and frames").

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct ColumnsOptions {
  /// The circumradius of each column's cross-section (a regular polygon). > 0.
  double thickness = 0.05;
  /// The sides of each column, in [3, 256].
  int sides = 4;
};

/// Replaces the surface by a frame: at each vertex of valence k a joint, a sphere with one n-gon facing
/// along each of its k edges (n = sides), and along each edge a column, a tube of n quads between the two
/// n-gons that face each other (connect_faces). The surface itself is then deleted; point spheres stay. For
/// E edges, V vertices with an edge, V1 of them of valence 1: V' = 2En, E' = 3En + 2E - V1, F' = 2V + En - V1
/// (point spheres added to V' and F'), so V' - E' + F' = 2V - 2E: a connected input gives one closed
/// component of genus E - V + 1, as wireframe. Refuses (ParameterError, nothing changed) a thickness not
/// finite or not > 0, sides outside [3, 256], and coordinates so large that the frame's could overflow.
/// O(size x sides), plus the size of a component per handle of it.
void columns(Transaction& tx, const ColumnsOptions& options = {});

/// The checks of columns, without changing anything.
void check_columns(const Mesh& mesh, const ColumnsOptions& options);

}  // namespace dlfl

#pragma once
// wireframe: every edge a beam and every face an opening through the frame (docs/modeling.md, "Shells and
// frames").

#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct WireframeOptions {
  /// The depth of the frame: how far its inner sheet lies below the outer one (as crust). > 0.
  double thickness = 0.05;
  /// How far the opening of each face lies inside its edges (the width of a beam's face is about twice
  /// this). > 0.
  double width = 0.05;
};

/// Insets every surface face by `width` (a ring of quads, as inset_face, with each corner moved to where the
/// face's edges moved inward by width meet), makes the crust of the result (thickness) and punches every
/// inset face, and every hole face, through to its twin by a tube of quads. For V vertices, E edges, F faces
/// (holes included), n_s the sides of the surface faces and n_h those of the hole faces: V' = 2(V + n_s),
/// E' = 2(E + 2n_s) + n_s + n_h, F' = 2(F + n_s) + n_s + n_h - 2F; on a closed mesh V' = 2V + 4E, E' = 12E,
/// F' = 6E. Always V' - E' + F' = 2V - 2E: a connected input gives one closed component of genus E - V + 1
/// (the cube: 5). Point spheres are left as they are. Returns the inner sheet's vertices. Refuses
/// (ParameterError, nothing changed) a thickness or width not finite or not > 0, and coordinates so large
/// that the frame's could overflow. O(size), plus the size of a component per handle of it.
std::vector<VertexId> wireframe(Transaction& tx, const WireframeOptions& options = {});

/// The checks of wireframe, without changing anything.
void check_wireframe(const Mesh& mesh, const WireframeOptions& options);

}  // namespace dlfl

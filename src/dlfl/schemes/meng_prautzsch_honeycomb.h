#pragma once
// The general honeycomb scheme H of Meng and Prautzsch (section 1.2 of "Mixed honeycomb pushing refinement",
// after Dyn, Levin and Liu): a convexity-preserving refinement of convex polyhedra that keeps the old
// vertices and cuts with planes. See docs/meng_prautzsch.md.

#include <glm/vec3.hpp>

#include <dlfl/mesh.h>
#include <dlfl/schemes/detail/meng_prautzsch_common.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// The parameters of H (see MpStepParams for their ranges and defaults):
/// - `tau`: where the f-face lies between its old face F (0) and v_F, the nearest vertex of Delta_F off F
///   (1); 0.5 is the midplane of the standard scheme.
/// - `ratio`: how each edge plane divides the edge's exterior angle: angle(n0, n) : angle(n, n1) = ratio : 1,
///   with n0 and n1 the normals of the faces on side 0 and side 1 of the edge and n the plane's normal; 1
///   bisects.
/// - `center`: the centre that must lie strictly inside. H itself does not move anything towards it: it only
///   takes part in the convexity check.
/// - `random`: random per-edge ratios and per-face taus.
struct MpHoneycombParams : MpStepParams {};

/// Throws InvalidArgument naming the parameter if tau is not in (0, 1), ratio not positive and finite, the
/// centre not finite, or epsilon not in (0, 1/2].
void check_mp_honeycomb_params(const MpHoneycombParams& params);

/// One step of H on a closed, strictly convex polyhedron with the centre strictly inside (checked by
/// `require_convex_polyhedron`: TopologyError or InvalidArgument naming the face or edge).
///
/// Each edge gets a plane through it that divides its exterior angle in the given ratio (its normal is the
/// great-circle interpolation of the two face normals). For a face F, Delta_F is the region outside F bounded
/// by F's plane and the planes of F's edges; its cross-section parallel to F at height t is the polygon
/// whose corner j lies where the planes of the two edges at corner j meet that plane, and v_F is at the
/// smallest height where an edge of that polygon shrinks to length 0. The f-face of F is the cross-section at
/// tau times that height. Each edge becomes a hexagonal e-face on its plane: its two end vertices and two
/// f-face vertices from each side. Old vertices stay.
///
/// Counts: V' = V + 2E, E' = 4E, F' = F + E; old vertices keep their valence, new ones have valence 3.
/// Output handles (input read in compacted handle order): vertex i is input vertex i, vertex V + k is the
/// f-face vertex at input corner k; face i is the f-face of input face i (its corner j from the input face's
/// corner j), face F + e is the e-face of input edge e, whose corners run: from(e), the two f-face vertices
/// of the face on side 1 (at from(e), then at to(e)), to(e), the two of the face on side 0 (at to(e), then at
/// from(e)). Corners are numbered face after face in that order. Faces are counter-clockwise seen from
/// outside; an edge's side 0 is its corner with the smaller handle, and edges are numbered in the order of
/// their side-0 corners (assembled directly with `MeshAssembler`, O(size)). The input is not modified.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): an old vertex <- itself, the f-face
/// vertex at corner c <- c; an f-face <- its face (parallel to it, same size), a hexagon <- its edge; an
/// f-face's side from the vertex of c to that of next(c) (along edge(c)) <- c, the edge from an old vertex
/// to the f-face vertex of one of its corners c <- c. By kind: vertices V from vertices, C from corners;
/// faces F from faces, E from edges; edges 2C from corners. Costs nothing when not asked for.
Mesh mp_honeycomb(const Mesh& mesh, const MpHoneycombParams& params = {}, Origins* origins = nullptr);

}  // namespace dlfl

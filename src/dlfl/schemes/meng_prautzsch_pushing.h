#pragma once
// The corner pushing scheme P of Meng and Prautzsch (section 4 of "Mixed honeycomb pushing refinement"), the
// dual of the honeycomb scheme H: cut every corner off along new edges between edge points, then push the old
// vertices towards the centre. See docs/meng_prautzsch.md.

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>

#include <dlfl/mesh.h>
#include <dlfl/schemes/detail/meng_prautzsch_common.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// The parameters of P (see MpStepParams for their ranges and defaults):
/// - `tau`: how far each old vertex moves towards the centre, as a fraction of the way to its extreme
///   position.
/// - `ratio`: where the new point divides each edge: |from(e) m| : |m to(e)| = ratio : 1; 1 is the midpoint.
/// - `center`: the centre the vertices move towards.
/// - `random`: random per-edge ratios and per-vertex taus.
struct MpPushingParams : MpStepParams {};

/// Throws InvalidArgument naming the parameter if tau is not in (0, 1), ratio not positive and finite, the
/// centre not finite, or epsilon not in (0, 1/2].
void check_mp_pushing_params(const MpPushingParams& params);

/// The extreme position of an old vertex p pushed towards centre o, as the fraction s of the way from p to o:
/// the 1-ring of p (triangles p m_i m_(i+1) over the edge points m_i around it, in rotation order) stays
/// convex at the edges p m_i until p reaches a plane through three consecutive edge points m_(i-1), m_i,
/// m_(i+1), where two triangles become coplanar. s is the smallest positive such hit, and at most 1 (the
/// centre itself: beyond it the centre would no longer be strictly inside). The edges between a triangle and
/// the face it was cut from only get more convex as p moves in, so they set no limit.
double pushing_extreme_fraction(const glm::dvec3& p, std::span<const glm::dvec3> ring,
                                const glm::dvec3& center);

/// One step of P on a closed, strictly convex polyhedron with the centre strictly inside (checked by
/// `require_convex_polyhedron`: TopologyError or InvalidArgument naming the face or edge).
///
/// Each edge gets a point dividing it in the given ratio. In each face, consecutive edge points are joined,
/// cutting it into one triangle per corner and a smaller central face of the same size on the old face's
/// plane. Each old vertex p then moves to p + tau * s * (o - p), with s from `pushing_extreme_fraction`.
///
/// Counts: V' = V + E, E' = 4E, F' = F + 2E; old vertices keep their valence, edge points have valence 6.
/// Output handles (input read in compacted handle order): vertex i is input vertex i (moved), vertex V + e is
/// the point on input edge e; face i is the central face of input face i (its corner j on the edge of the
/// input face's corner j), face F + k is the triangle at input corner k: its vertex, the point on its
/// outgoing edge, the point on its incoming edge. Corners are numbered face after face in that order. Faces
/// are counter-clockwise seen from outside; an edge's side 0 is its corner with the smaller handle, and edges
/// are numbered in the order of their side-0 corners (assembled directly with `MeshAssembler`, O(size)). The
/// input is not modified.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): an old vertex (moved) <- itself, an
/// edge point <- its edge; a central face <- its face (on its plane, same size), the triangle at corner c <-
/// c; each half of an old edge <- that edge, a central face's side between the points of edge(c) and
/// edge(next c) <- next(c), the corner it cuts off. By kind: vertices V from vertices, E from edges; faces F
/// from faces, C from corners; edges 2E from edges, C from corners. Costs nothing when not asked for.
Mesh mp_pushing(const Mesh& mesh, const MpPushingParams& params = {}, Origins* origins = nullptr);

}  // namespace dlfl

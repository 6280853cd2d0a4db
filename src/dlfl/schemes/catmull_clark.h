#pragma once
// Catmull-Clark subdivision on any polygon mesh.

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// One Catmull-Clark step, with the standard rules:
/// - face point: the centroid of the face;
/// - edge point: the average of the edge's two ends and the two adjacent face points;
/// - vertex point: (Q + 2R + (n-3) S) / n, with Q the average of the adjacent face points, R the average of
///   the midpoints of the n incident edges, S the old position.
///
/// Every corner of the input becomes one quad (vertex point, edge point of the edge leaving the corner, face
/// point, edge point of the edge arriving), so F' = number of corners, V' = V + E + F, E' = 2E + corners.
/// Output handles: vertex points first (in input vertex order), then edge points, then face points; quad k
/// comes from the input's k-th corner. 2-gons are fine. Throws TopologyError for a point sphere (a vertex
/// with no edge has no vertex rule). The input is not modified.
///
/// Open meshes (hole faces), by `boundary.rule` (docs/boundaries.md):
/// - `curve`, the default: the cubic B-spline boundary rule. A hole face gets no face point and stays one
///   hole face, whose sides are the halves of its edges (2n corners for n). A boundary edge's point is its
///   midpoint; a boundary vertex with one hole corner goes to (1/8, 6/8, 1/8) of its two neighbours along the
///   loop and itself; a sharp boundary vertex stays (marked with the `sharp` vertex attribute, with exactly
///   two edges when `boundary.sharp_corners`, or where loops touch). Inner edges and vertices keep the rules
///   above. So the boundary depends only on the boundary polygon, and converges to its uniform cubic B-spline
///   (a chain between sharp vertices: to the B-spline of the chain extended by 2 p0 - p1 at each end, which
///   interpolates them). Counts, with F and C of the surface faces, H holes with B corners in all:
///   V' = V + E + F, E' = 2E + C, F' = C + H, B' = 2B (C = 2E - B). Numbering: vertex points, edge points,
///   then the face points of the surface faces in face order; the quads of the surface corners in corner
///   order, then the hole faces in face order. The result carries the input's `sharp` marks on the vertex
///   points (a corner keeps its two edges, so it stays a corner).
/// - `hole`: hole faces are subdivided like faces (the boundary is smoothed as if capped, so it depends on
///   the faces inside) and their quads stay holes; the counts above with the holes counted as faces. This is
///   what a log written before boundary rules replays with.
/// A closed mesh gets the same result either way.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself, tombstones and all): a vertex point <-
/// its vertex, an edge point <- its edge, a face point <- its face; the quad of corner c <- c (it holds that
/// corner's vertex point and face point); each half of an old edge <- that edge, and the edge from the edge
/// point of edge(c) to the face point of face(c) <- corner c; under `curve`, a hole face <- the input's hole
/// face. By kind: vertices V from vertices, E from edges, F from faces; faces C from corners (and H from
/// faces); edges 2E from edges, C from corners. Costs nothing when not asked for.
///
/// The registered scheme's counts (V + E + F, 4E, 2E from V, E, F with holes counted as faces) are exact on
/// closed meshes and under `hole`, and bound the curve rule's from above (F + H >= F, C <= 2E).
Mesh catmull_clark(const Mesh& mesh, const BoundaryOptions& boundary, Origins* origins = nullptr);

/// The same with the default boundary options (`curve`, sharp corners kept).
Mesh catmull_clark(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl

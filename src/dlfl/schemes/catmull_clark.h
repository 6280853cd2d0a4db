#pragma once
// Catmull-Clark subdivision on any polygon mesh.

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// One Catmull-Clark step, with the standard rules:
/// - face point: the centroid of the face;
/// - edge point: the average of the edge's two ends and the two adjacent face points;
/// - vertex point: (Q + 2R + (n-3) S) / n, with Q the average of the adjacent face points, R the average of
/// the
///   midpoints of the n incident edges, S the old position.
///
/// Every corner of the input becomes one quad (vertex point, edge point of the edge leaving the corner, face
/// point, edge point of the edge arriving), so F' = number of corners, V' = V + E + F, E' = 2E + corners.
/// Output handles: vertex points first (in input vertex order), then edge points, then face points; quad k
/// comes from the input's k-th corner. 2-gons are fine. Hole faces are subdivided like faces (the boundary is
/// smoothed as if capped) and their quads stay holes. Throws TopologyError for a point sphere (a vertex with
/// no edge has no vertex rule). The input is not modified.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself, tombstones and all): a vertex point <-
/// its vertex, an edge point <- its edge, a face point <- its face; quad k <- the input corner it is made for
/// (it holds that corner's vertex point and face point); each half of an old edge <- that edge, and the edge
/// from the edge point of edge(c) to the face point of face(c) <- corner c. By kind: vertices V from
/// vertices, E from edges, F from faces; faces C from corners; edges 2E from edges, C from corners. Costs
/// nothing when not asked for.
Mesh catmull_clark(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl

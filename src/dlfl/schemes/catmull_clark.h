#pragma once
// Catmull-Clark subdivision on any polygon mesh.

#include <dlfl/mesh.h>

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
Mesh catmull_clark(const Mesh& mesh);

}  // namespace dlfl

#pragma once
// multi_connect: k faces joined through one hub, TopMod's multi-face handle with the convex-hull method
// (docs/modeling.md, "Hulls").

#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct MultiConnectOptions {
  /// How far the hub's points are from the faces' vertices' centroid, as a fraction of the vertices'
  /// distance from it: in (0, 1).
  double scale = 0.5;
};

struct MultiConnectResult {
  /// The hub's vertices: the copies of the selected faces' vertices, in the order they first occur along
  /// the faces as given.
  std::vector<VertexId> hub_vertices;
  /// The tubes' faces, face by face in the order given, each tube as connect_faces lists it.
  std::vector<FaceId> tube_faces;
};

/// Joins k >= 3 faces through one hub. The hub is the convex hull (convex_hull.h) of the faces' distinct
/// vertices moved toward their centroid c, p -> c + scale (p - c); each selected face has a scaled copy
/// among its faces, with the same vertices. The hub is added as a new component (through `tx`, so undo is
/// the record), oriented against the faces: turned inside out (a cavity) when the faces face away from it,
/// as they do on a convex part of a surface, and as the hull when they face toward it. Then each face is
/// joined to its copy by connect_faces (a tube of n quads, the face's first corner to its copy). On one
/// component the genus grows by k - 1 (the first tube joins the hub, each further one adds a handle); faces
/// of several components join them all into one.
///
/// Counts, with V_h the number of distinct vertices of the faces, F_h the number of faces of the hub
/// (E_h = V_h + F_h - 2) and n_i the sides of face i: V + V_h, E + E_h + sum n_i, F + F_h + sum n_i - 2k; the
/// Euler characteristic changes by 2 - 2k.
///
/// Refuses (ParameterError, nothing changed): fewer than 3 faces, an empty list, a face listed twice, a
/// removed, hole or point-sphere face (naming "faces"); a scale not in (0, 1) or not finite ("scale"); and,
/// naming "faces", a hub that would be degenerate: the scaled vertices coplanar (or refused by convex_hull
/// for another reason), a vertex that would not be a corner of the hub, a face whose copy would not be a
/// face of the hub (it is not planar and strictly convex, or not on the hull of the selected vertices, or
/// in the plane of another face's vertices), or faces of which some face away from the hub and some toward
/// it. Expected O(k log k) for the hub in the number of the faces' corners, plus the tubes.
MultiConnectResult multi_connect(Transaction& tx, std::span<const FaceId> faces,
                                 const MultiConnectOptions& options = {});

/// The checks of multi_connect, without changing anything; throws ParameterError as it does.
void check_multi_connect(const Mesh& mesh, std::span<const FaceId> faces,
                         const MultiConnectOptions& options = {});

}  // namespace dlfl

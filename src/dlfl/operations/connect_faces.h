#pragma once
// connect_faces: a tube from one face to another, what TopMod calls "add hole/handle". One INSERTEDGE
// between a corner of each face merges the two faces (adding a handle, or joining two components); more
// INSERTEDGEs split the merged face into the tube's faces. With several segments the tube's long edges are
// subdivided at rings of new vertices placed along a curve, and INSERTEDGEs between the rings split each
// tube face into a column of faces.

#include <cstdint>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// The curve the tube's rings follow from face1 to face2.
enum class TubeCurve : std::uint8_t {
  /// The straight segment between the face centroids; each ring is the two end polygons blended, turning
  /// about the segment where the correspondence turns (a twist), so twisted rings do not collapse.
  line,
  /// A cubic Hermite curve between the centroids, leaving face1 along its normal and entering face2 against
  /// its normal (tangents weight1 and weight2 times the distance between the centroids); the rings are
  /// carried along it in rotation-minimizing frames.
  hermite,
  /// Every ring vertex on its own cubic Bezier curve from its face1 corner to its face2 corner, with inner
  /// control points a third of those tangents off the faces.
  bezier,
};

struct ConnectFacesOptions {
  /// The corner of face1 the first new edge starts at; invalid: chosen (see `connect_faces`).
  CornerId corner1{};
  /// The corner of face2 that corner1 pairs with (before `twist`); invalid: chosen.
  CornerId corner2{};
  /// Faces along the tube, 1 to 1024.
  int segments = 1;
  TubeCurve curve = TubeCurve::line;
  /// Scales of the tangents at face1 and face2 (hermite, bezier), at least 0.
  double weight1 = 1.0;
  double weight2 = 1.0;
  /// Turns the correspondence by this many corners: corner1 pairs with the corner `twist` steps after
  /// corner2 along face2 (negative: before).
  std::int64_t twist = 0;
  /// Scales the middle ring (1: unchanged), along 1 + (pinch - 1) 4t(1 - t); at least 0.
  double pinch = 1.0;
  /// Pushes the middle rings outward, away from the curve, by bubble x the mean radius of the two ends x
  /// 2 sqrt(t(1 - t)) (a round bulge); at least 0.
  double bubble = 0.0;
};

/// What `connect_faces` made.
struct ConnectFacesResult {
  /// The tube's faces, ring by ring from face1's end to face2's end, each ring in the order of the
  /// correspondence (starting at the face between the first two long edges): segments x max(n1, n2).
  std::vector<FaceId> faces;
  /// The new vertices, ring by ring from face1's end: (segments - 1) x max(n1, n2).
  std::vector<VertexId> vertices;
  /// The first edge, the one that merged the two faces.
  EdgeId edge;
  /// The corners the tube was built from (corner2 before the twist).
  CornerId corner1;
  CornerId corner2;
};

/// The corner pair a tube starts from, as `connect_faces` resolves it.
struct TubeEnds {
  CornerId corner1;
  CornerId corner2;
};

/// Connects face1 (n1 sides) and face2 (n2 sides) with a tube. Let m = max(n1, n2) and s = segments. The
/// correspondence runs forward along face1 from corner1 and backward along face2 from its partner (corner2
/// turned by `twist`), as a tube needs to keep the orientation: m long edges, the k-th joining corner
/// floor(k n1 / m) of face1 and corner floor(k n2 / m) of face2. Equal sizes give m quads; different sizes
/// give min(n1, n2) quads and |n1 - n2| triangles (never a face of more than four sides).
///
/// Counts: V + m(s - 1), E + m s + m(s - 1), F - 2 + m s. On one component the Euler characteristic drops
/// by 2 (the genus grows by one); faces on two components join them into one.
///
/// Corners left out are chosen: the closest pair of corners (one in each face; or the corner closest to the
/// given one) whose correspondence joins no vertex to itself (the faces may share vertices). Ties go to the
/// first corners along the faces from their first corners.
///
/// Hole faces: either face or both may be holes (both: two boundary loops bridged by a tube); every face of
/// the tube is a surface face.
///
/// Throws ParameterError naming the argument, before anything changes, for: a removed face, the same face
/// twice, a point sphere's face, a corner that is removed or not in its face, a given correspondence that
/// would join a vertex to itself (or no such correspondence at all), segments outside [1, 1024], a negative
/// or non-finite weight, pinch or bubble.
ConnectFacesResult connect_faces(Transaction& tx, FaceId face1, FaceId face2,
                                 const ConnectFacesOptions& options = {});

/// The checks of `connect_faces`, without changing anything; throws ParameterError as it does. Returns the
/// corner pair the tube would start from (the given corners, or the chosen ones).
TubeEnds check_connect_faces(const Mesh& mesh, FaceId face1, FaceId face2,
                             const ConnectFacesOptions& options = {});

}  // namespace dlfl

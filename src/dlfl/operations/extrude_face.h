#pragma once
// extrude_face: TopMod's family of face extrusions, built from the Euler operators (docs/modeling.md,
// "Extrusions"). The face moves out along a direction and new faces join it to where it was; the style says
// which faces. Every style keeps the Euler characteristic (V - E + F), and hole flags and orientation: the
// new faces are surface faces turned as the face was.

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// What an extrusion builds on a face of n sides, with s segments (the change of V, E and F):
enum class ExtrudeStyle : std::uint8_t {
  /// n quads per segment joining the moved face to where it was: V+n*s, E+2n*s, F+n*s.
  cubical,
  /// As cubical, the moved face first shrunk by Doo-Sabin's mask for the face (half size for a regular
  /// polygon): V+n*s, E+2n*s, F+n*s.
  doo_sabin,
  /// An antiprism band per segment: the new corners sit over the edges of the old face (for a regular
  /// polygon, the same polygon turned by pi/n), 2n triangles join them: V+n*s, E+3n*s, F+2n*s. On a regular
  /// triangle at distance sqrt(2/3)*edge, a regular octahedron.
  octahedral,
  /// A cone: one apex over the centroid joined to every corner: V+1, E+n, F+n-1 (segments 1).
  stellate,
  /// The cone, each of its triangles stellated again at its centroid in the plane of the face (the first
  /// apex then raised): V+n+1, E+4n, F+3n-1 (segments 1).
  double_stellate,
  /// Per segment: three new rings, 2n pentagons and the moved face: V+3n*s, E+5n*s, F+2n*s. On a regular
  /// pentagon at distance sqrt(5/2 + 11 sqrt(5)/10)*edge, a regular dodecahedron.
  dodecahedral,
  /// Per segment: n triangles at the old edges, n pentagons each stellated into 5 triangles, the moved face:
  /// V+3n*s, E+9n*s, F+6n*s. On a regular triangle at distance phi^2/sqrt(3)*edge, a regular icosahedron.
  icosahedral,
  /// Five Doo-Sabin rings of falling height and width, then a cone: V+5n+1, E+11n, F+6n-1 (segments 1).
  dome,
};

/// The style's name as the operation spells it: "cubical", "doo-sabin", "double-stellate", ...
std::string_view to_string(ExtrudeStyle style);

struct ExtrudeFaceOptions {
  /// How far the face moves along the direction (negative: inwards). The total, whatever the segments.
  double distance = 1.0;
  /// How many times the style's unit is built, each over distance/segments, turning and scaling by its
  /// share; the last face ends where one segment would have put it. 1 for stellate, double-stellate and
  /// dome. In [1, 10000].
  int segments = 1;
  /// The moved face turns by this about the direction through its centroid (counter-clockwise seen from the
  /// direction's tip). 0 for stellate and double-stellate.
  double rotate_degrees = 0.0;
  /// The moved face is scaled by this about its centroid; > 0. 1 for stellate and double-stellate.
  double scale = 1.0;
  /// Where the face moves (normalised); the face's normal when absent. Not zero.
  std::optional<glm::dvec3> direction;
  ExtrudeStyle style = ExtrudeStyle::cubical;
};

/// What an extrusion made on one face.
struct ExtrudeFaceResult {
  /// The moved face (the last segment's); invalid for stellate, double-stellate and dome, which end in a
  /// cone.
  FaceId end_face;
  /// The cone's apex for stellate, double-stellate and dome; invalid otherwise.
  VertexId apex;
};

/// Extrudes `face` (see ExtrudeStyle for the counts). Checks everything first (the refusals of
/// extrude_faces) and throws ParameterError naming "face" or the option at fault, with the mesh unchanged.
/// O(n*segments).
ExtrudeFaceResult extrude_face(Transaction& tx, FaceId face, const ExtrudeFaceOptions& options = {});

/// Extrudes each face on its own, as extrude_face would one after the other (the counts add up). The results
/// are in the order of `faces`. Refused before any change, with a ParameterError naming `face_parameter`: an
/// empty list, a face listed twice, a removed, hole or point-sphere face, a face with no normal (a zero
/// Newell vector) when no direction is given; naming the option: a zero direction, segments out of
/// [1, 10000] or not 1 for a cone style, rotate_degrees or scale other than 0 and 1 for stellate and
/// double-stellate, a scale not > 0, a number not finite, new positions that would not be finite.
std::vector<ExtrudeFaceResult> extrude_faces(Transaction& tx, std::span<const FaceId> faces,
                                             const ExtrudeFaceOptions& options = {},
                                             std::string_view face_parameter = "faces");

}  // namespace dlfl

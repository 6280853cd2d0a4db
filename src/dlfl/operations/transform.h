#pragma once
// transform: every vertex moved by one affine map (scale, then rotate, about a centre; then translate).

#include <glm/vec3.hpp>
#include <optional>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct TransformOptions {
  glm::dvec3 translate{0.0};
  /// Per axis. No component may be zero (that would flatten the mesh), and an odd number of negative ones is
  /// refused: such a map is a mirror, which would turn every face inside out (reverse_orientation does
  /// that on purpose).
  glm::dvec3 scale{1.0};
  /// Need not be of unit length; must not be zero.
  glm::dvec3 rotate_axis{0, 0, 1};
  /// Counter-clockwise about the axis, seen from its tip (the right-hand rule).
  double rotate_degrees = 0.0;
  /// The fixed point of the scale and the rotation; none: the centre of the bounding box of the vertices.
  std::optional<glm::dvec3> center;
};

/// Moves every vertex p (set_position) to center + R(scale * (p - center)) + translate: first the scale per
/// axis about the centre, then the rotation R about the axis through the centre, then the translation. The
/// counts do not change: V+0, E+0, F+0. A vertex the map leaves where it is (the identity, or the centre) is
/// not written. O(V).
///
/// Throws ParameterError (mesh unchanged) naming "rotate_axis" for a zero axis, "scale" for a zero component
/// or an odd number of negative ones, and "scale" or "translate" when a position would not be finite.
void transform(Transaction& tx, const TransformOptions& options);

/// The refusals of transform, without changing anything. Throws ParameterError.
void check_transform(const Mesh& mesh, const TransformOptions& options);

}  // namespace dlfl

#pragma once
// How a subdivision scheme treats the boundary of an open mesh: its boundary loops (hole faces).

#include <cstdint>
#include <string_view>

namespace dlfl {

/// What a scheme does at the boundary loops (hole faces) of an open mesh.
enum class BoundaryRule : std::uint8_t {
  /// The scheme's boundary rule: the boundary of the result depends only on the boundary polygon, and
  /// converges to a curve of it (the limit curve each scheme's header names).
  curve,
  /// A hole face is subdivided like any other face and its pieces stay holes (the behaviour before boundary
  /// rules, and what a log without a `boundary` field replays with).
  hole,
};

/// "curve" or "hole".
std::string_view to_string(BoundaryRule rule);

/// The name of the boolean vertex attribute by which a user marks boundary vertices to be kept sharp. A
/// scheme with a boundary rule keeps each marked vertex where it is, and marks the vertex it becomes in the
/// result, so that the mark holds over every step.
inline constexpr std::string_view sharp_vertex_attribute = "sharp";

/// The boundary options shared by every scheme that takes open meshes.
struct BoundaryOptions {
  BoundaryRule rule = BoundaryRule::curve;
  /// Under `curve`: a boundary vertex with exactly two edges (the corner of a grid) stays where it is, as do
  /// the vertices marked with the `sharp` attribute. False: only the marked ones.
  bool sharp_corners = true;
};

}  // namespace dlfl

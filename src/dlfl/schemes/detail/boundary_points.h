#pragma once
// Internal to the schemes with a boundary rule (Doo-Sabin, the honeycombs, dual): which boundary vertices are
// sharp, the marks they leave on the result, and the points of the boundary rules, written once so that two
// meshes sharing a boundary loop (traversed in opposite directions) compute bit-identical boundary points.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>

namespace dlfl::detail {

/// True if some face of `mesh` is a hole.
bool has_hole(const Mesh& mesh);

/// By vertex handle index (sized by the vertex capacity): true for the boundary vertices (those with a hole
/// face around them) that the boundary rule keeps in place: those marked with the boolean vertex attribute
/// `sharp`, and, when `options.sharp_corners`, those with exactly two edges. All false under
/// BoundaryRule::hole. Throws InvalidArgument, naming the scheme, if the mesh has a `sharp` vertex attribute
/// that is not boolean.
std::vector<bool> sharp_boundary_vertices(const Mesh& mesh, const BoundaryOptions& options,
                                          const char* scheme);

/// The `sharp` vertex attribute of `mesh` (boundary_rule.h), if it has one. Throws InvalidArgument, naming
/// `scheme`, if it is not boolean: call it before any work. Shared by every scheme's curve rule.
std::optional<ConstAttribute<VertexId, bool>> sharp_marks(const Mesh& mesh, const char* scheme);

/// Marks the vertices with these indices of `result` sharp (the boolean attribute `sharp`, default false),
/// adding the attribute only if there is one to mark.
void mark_sharp(Mesh& result, std::span<const std::uint32_t> vertices);

/// Chaikin's point on the boundary edge from a to b, near a: 3/4 a + 1/4 b, or, for the clamped quadratic
/// B-spline at a sharp end, a itself (a sharp) or the midpoint (b sharp).
inline glm::dvec3 chaikin_point(const glm::dvec3& a, const glm::dvec3& b, bool a_sharp, bool b_sharp) {
  if (a_sharp) return a;
  if (b_sharp) return 0.5 * (a + b);
  return 0.75 * a + 0.25 * b;
}

/// The midpoint of a boundary edge (commutative, so both sides of a shared loop agree bit for bit).
inline glm::dvec3 boundary_midpoint(const glm::dvec3& a, const glm::dvec3& b) { return 0.5 * (a + b); }

/// The point the honeycombs put at boundary vertex v between its boundary neighbours u and w: v itself when
/// sharp, else v/2 + (u + w)/4, the midpoint of the chord between the midpoints of its two boundary edges
/// (Zhang-Wang's formula (15) with s_n = 1/2).
inline glm::dvec3 honeycomb_boundary_vertex(const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w,
                                            bool sharp) {
  if (sharp) return v;
  return 0.5 * v + 0.25 * (u + w);
}

}  // namespace dlfl::detail

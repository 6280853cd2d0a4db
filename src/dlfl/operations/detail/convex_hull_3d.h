#pragma once
// Internal to the hulls (convex_hull, dual_hull, multi_connect): the convex hull of a point set as a closed
// mesh of planar, strictly convex faces. See convex_hull.h for the contract and docs/modeling.md, "Hulls",
// for the method and its tolerances.

#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/operation.h>

namespace dlfl::detail {

/// Two faces whose normals differ by at most this angle (radians) are merged into one face, and a vertex at
/// which a face turns by at most this angle is dropped. Four times the angle tolerance of the convexity
/// check (ConvexityOptions), so that what is left passes it.
inline constexpr double hull_angle_tolerance = 4e-9;
/// A face merged by the angle rule must keep its vertices this close to its plane, relative to the
/// diagonal of the bounding box (a quarter of the convexity check's planarity tolerance).
inline constexpr double hull_planarity_tolerance = 2.5e-10;
/// Points whose hull is thinner than this, relative to the diagonal, are refused as nearly coplanar.
inline constexpr double hull_flatness_tolerance = 1e-8;

/// A hull: `mesh`'s vertex i is `points[source[i]]` (the hull's vertices in increasing order of their
/// index in the points); faces counter-clockwise seen from outside, in a canonical order.
struct HullMesh {
  Mesh mesh;
  std::vector<std::uint32_t> source;
};

/// The hull, or why there is none (`refusal` non-empty, a sentence without the operation's name).
struct HullOutcome {
  HullMesh hull;
  std::string refusal;
};

/// The convex hull of `points` (see convex_hull.h). `name_of(i)` names point i in messages.
HullOutcome hull_of_points(std::span<const glm::dvec3> points,
                           const std::function<std::string(std::uint32_t)>& name_of);

/// The hull of a point set, or a ParameterError "OP: parameter points: why" (points named "point i").
HullMesh hull_of_point_set(std::span<const glm::dvec3> points, std::string_view op);

/// The hull of the mesh's live vertices, refusals naming "mesh"; `source` holds vertex handle indices.
HullMesh hull_of_mesh(const Mesh& mesh, std::string_view op);

/// The declaration of a hull operation: a replace operation without parameters whose new mesh is
/// `build(current)`.
OperationSpec hull_operation(std::string name, std::string doc, Mesh (*build)(const Mesh&));

/// Declares every attribute of `from` on `to` (same kind, name and default).
void declare_attributes(const Mesh& from, Mesh& to);

}  // namespace dlfl::detail

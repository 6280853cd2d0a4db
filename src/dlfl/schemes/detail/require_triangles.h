#pragma once
// Internal to the schemes: the input check of the triangle schemes (Loop, sqrt(3)).

#include <string_view>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// Whether a scheme on triangles takes hole faces: Loop does (triangular holes), sqrt(3) has no boundary
/// rule.
enum class TriangleHoles { allowed, refused };

/// Refuses, in face order, a point sphere, a face that is not a triangle and, when `holes` is `refused`, any
/// hole: TopologyError "SCHEME: f3 has 4 corners; TITLE needs triangles" and the like, naming the handles of
/// `mesh` (check the input, not a compacted copy). `title` names the scheme in prose ("Loop subdivision").
void require_triangles(const Mesh& mesh, std::string_view scheme, std::string_view title,
                       TriangleHoles holes);

}  // namespace dlfl::detail

#pragma once
// Internal to planarize and the honeycomb's `planarize` rule: one round of moves towards the faces' planes.

#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// One round of the `planarize` operation, as moves not yet applied: the least-squares plane of every surface
/// face of 4 or more corners, and for every vertex of such faces the mean of its projections onto the planes
/// of its faces (a face planar to 1e-12 of its mean edge length counts as the vertex where it is), all from
/// the current positions. Only vertices that move, to finite positions, are listed, in handle order.
std::vector<std::pair<VertexId, glm::dvec3>> planarize_moves(const Mesh& mesh);

}  // namespace dlfl::detail

#pragma once
// Internal to sqrt(3): what its step on closed meshes (sqrt3.cpp) and its step under the curve boundary rule
// (sqrt3_boundary.cpp) share.

#include <optional>
#include <span>

#include <dlfl/mesh.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl::detail {

/// Kobbelt's vertex rule on vertices 0 .. V-1 of `out`: (1 - a_n) S + a_n / n (sum of the n neighbours), from
/// the sums of each vertex's neighbours and its valence.
void set_sqrt3_vertex_points(const Mesh& m, std::span<const glm::dvec3> sum,
                             std::span<const std::uint32_t> valence, MeshAssembler& out);

/// One sqrt(3) step under the curve rule on dense `m` (the input `input` compacted) with hole faces: see
/// sqrt3.h. Checks its input (bare edges, a face with two edges to trisect) before any work.
Mesh sqrt3_open(const Mesh& input, const Mesh& m, const BoundaryOptions& boundary,
                const std::optional<ConstAttribute<VertexId, bool>>& marks, Origins* origins);

}  // namespace dlfl::detail

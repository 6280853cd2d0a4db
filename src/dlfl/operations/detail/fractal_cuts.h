#pragma once
// Internal to sierpinski and menger: the steps they share. Both cut every edge in three and every corner of
// every face off by an edge between the two points next to it, and both refuse the same meshes and shares.

#include <array>
#include <glm/vec3.hpp>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl::detail {

/// The points at share t of the way from a to b and from b to a.
std::array<glm::dvec3, 2> points_in_from_ends(const glm::dvec3& a, const glm::dvec3& b, double t);

/// Where every edge is cut in three: the edges, and per edge index the points at share t of its length from
/// from(e) and from to(e).
struct EdgeCuts {
  std::vector<EdgeId> edges;
  std::vector<std::array<glm::dvec3, 2>> at;
};

/// The cuts of every edge of the mesh at share t from each end; their points are appended to `positions`
/// (for the finiteness check of the caller's plan).
EdgeCuts plan_edge_cuts(const Mesh& mesh, double t, std::vector<glm::dvec3>& positions);

/// Cuts every planned edge in three (divide_in_three): V+2E, E+2E.
void cut_edges(Transaction& tx, const EdgeCuts& cuts);

/// Cuts edge e in three by two new vertices, at `near_from` (on the piece that keeps e, from(e) to it) and
/// then at `near_to`: V+2, E+2, F+0; each face beside e grows by two corners. Corners keep their vertices.
/// Returns the two vertices in that order.
std::array<VertexId, 2> divide_in_three(Transaction& tx, EdgeId e, const glm::dvec3& near_from,
                                        const glm::dvec3& near_to);

/// Cuts the corner c off its face by an edge from next(c) to prev(c) (a split: V+0, E+1, F+1). The edge's
/// side 0 starts at vertex(next(c)) in the triangle (prev(c), c, next(c)); its side 1 starts at
/// vertex(prev(c)) in the rest of the face, whose corner at vertex(next(c)) is still next(c).
EdgeId cut_corner(Transaction& tx, CornerId c);

/// The corner of every face that has edges, in handle order: the corners the two operations cut.
std::vector<CornerId> corners_with_edges(const Mesh& mesh);

/// Refuses `param` (a ParameterError, "OP: parameter PARAM = X is outside (0, HI): WHY") unless share is
/// finite and in (0, hi).
void require_share(std::string_view op, std::string_view param, double share, double hi,
                   std::string_view why);

/// Refuses `param` if a vertex has valence 1: its face comes back along the same edge, so cutting its corner
/// would join a point to itself.
void refuse_dangling_edges(const Mesh& mesh, std::string_view op, std::string_view param);

/// Refuses `param` unless every position is finite, naming what they are in the message.
void require_finite_positions(std::string_view op, std::string_view param, const std::vector<glm::dvec3>& ps,
                              std::string_view what);

}  // namespace dlfl::detail

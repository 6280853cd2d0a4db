#pragma once
// Internal to the extrusions (extrude_face, inset_face): the Euler-operator building blocks that grow new
// faces inside a face. Each takes the face as its corners in order (c[i+1] == next(c[i]), c[i] at p_i, its
// edge running p_i -> p_{i+1}) and changes the mesh only through the Transaction. The corners c[i] keep their
// vertex and edge (insert_edge never moves them), which is what lets a stage find its way: the bookkeeping is
// written out at each function. Every split cuts off a triangle or a quad, so each costs O(1) and a stage
// O(n).

#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl::detail {

/// The corners of a face, along `next` from `first`.
std::vector<CornerId> corners_from(const Mesh& mesh, CornerId first);

/// A ring of quads: a new vertex q_i at positions[i] for each corner c_i, joined to p_i and to q_{i+1}; the
/// face becomes the n quads (p_i, p_{i+1}, q_{i+1}, q_i) and the inner n-gon q_0 ... q_{n-1}, oriented as the
/// face was. V+n, E+2n, F+n. Returns the corners of the inner face, the i-th at q_i.
std::vector<CornerId> grow_quad_ring(Transaction& tx, std::span<const CornerId> face,
                                     std::span<const glm::dvec3> positions);

/// A ring of triangles (an antiprism band): a new vertex m_i at positions[i] for each edge p_i p_{i+1},
/// joined to both its ends and to m_{i+1}; the face becomes the 2n triangles (p_i, p_{i+1}, m_i) and
/// (m_{i-1}, p_i, m_i) and the inner n-gon m_0 ... m_{n-1}. V+n, E+3n, F+2n. Returns the corners of the inner
/// face, the i-th at m_i.
std::vector<CornerId> grow_triangle_ring(Transaction& tx, std::span<const CornerId> face,
                                         std::span<const glm::dvec3> positions);

/// A cone: a new vertex at `apex` joined to every corner; the face becomes the n triangles (p_i, p_{i+1},
/// apex), the i-th holding c_i. V+1, E+n, F+n-1. Returns the apex.
VertexId grow_cone(Transaction& tx, std::span<const CornerId> face, const glm::dvec3& apex);

/// Deletes the edges of the corners (a ring that a later stage grew on), each merging the two faces beside
/// it. E-k, F-k for k corners whose edges separate distinct faces.
void remove_edges_of(Transaction& tx, std::span<const CornerId> corners);

}  // namespace dlfl::detail

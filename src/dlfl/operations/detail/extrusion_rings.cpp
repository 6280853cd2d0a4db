#include <dlfl/operations/detail/extrusion_rings.h>

namespace dlfl::detail {
namespace {

// Joins a new point sphere at `position` to corner c by insert_edge (a merge: the sphere's face goes, the
// larger face stays). The face then runs ..., n1 (at vertex(c), along the new edge), s (the sphere's corner,
// along the edge back), c, ...: prev(c) is s and prev(s) is n1. Returns n1.
CornerId add_spike(Transaction& tx, CornerId c, const glm::dvec3& position) {
  const VertexId v = tx.create_vertex(position);
  const InsertEdgeResult r = tx.insert_edge(c, tx.mesh().corner(v));
  return tx.mesh().corner(r.edge, 0);
}

}  // namespace

std::vector<CornerId> corners_from(const Mesh& mesh, CornerId first) {
  std::vector<CornerId> out;
  CornerId c = first;
  do {
    out.push_back(c);
    c = mesh.next(c);
  } while (c != first);
  return out;
}

std::vector<CornerId> grow_quad_ring(Transaction& tx, std::span<const CornerId> face,
                                     std::span<const glm::dvec3> positions) {
  const Mesh& m = tx.mesh();
  const std::size_t n = face.size();
  for (std::size_t i = 0; i < n; ++i) add_spike(tx, face[i], positions[i]);
  // Now prev(c_i) is the corner at q_i running back to p_i, next(c_i) the corner at p_{i+1} running to
  // q_{i+1}, and the corner after that sits at q_{i+1} in the angle that faces quad i. An edge from there to
  // prev(c_i) cuts off quad i = (c_i, next(c_i), the new corner at q_{i+1}, prev(c_i)); its side 1 starts at
  // q_i and runs to q_{i+1} along the inner face. The splits keep those relations for the corners not yet
  // used: the last one finds at q_0 the side-1 corner of the first split.
  std::vector<CornerId> inner(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CornerId at_next = m.next(m.next(face[i]));
    const InsertEdgeResult r = tx.insert_edge(at_next, m.prev(face[i]));
    inner[i] = m.corner(r.edge, 1);
  }
  return inner;
}

std::vector<CornerId> grow_triangle_ring(Transaction& tx, std::span<const CornerId> face,
                                         std::span<const glm::dvec3> positions) {
  const Mesh& m = tx.mesh();
  const std::size_t n = face.size();
  // Spike i, from p_i to m_i, leaves p_i from to_m[i].
  std::vector<CornerId> to_m(n);
  for (std::size_t i = 0; i < n; ++i) to_m[i] = add_spike(tx, face[i], positions[i]);
  // Lower triangle i: from next(c_i) (at p_{i+1}) to prev(c_i) (at m_i) cuts off (p_i, p_{i+1}, m_i).
  for (std::size_t i = 0; i < n; ++i) tx.insert_edge(m.next(face[i]), m.prev(face[i]));
  // The face left runs m_{j-1}, p_j (corner to_m[j]), m_j, p_{j+1}, ... An edge from next(to_m[j]) (at m_j)
  // to prev(to_m[j]) (at m_{j-1}) cuts off the upper triangle (m_{j-1}, p_j, m_j); its side 1 starts at
  // m_{j-1} along the inner face. Going j = 1, ..., n-1, 0 each split finds its neighbours in place.
  std::vector<CornerId> inner(n);
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t j = k % n;
    const InsertEdgeResult r = tx.insert_edge(m.next(to_m[j]), m.prev(to_m[j]));
    inner[k - 1] = m.corner(r.edge, 1);
  }
  return inner;
}

VertexId grow_cone(Transaction& tx, std::span<const CornerId> face, const glm::dvec3& apex) {
  const Mesh& m = tx.mesh();
  const VertexId a = tx.create_vertex(apex);
  tx.insert_edge(face[0], m.corner(a));
  // prev(c_i) is at the apex, running to p_i; an edge from c_{i+1} to it cuts off triangle (p_i, p_{i+1},
  // apex), and the new corner at the apex becomes prev(c_{i+1}). The last triangle is what remains.
  for (std::size_t i = 0; i + 1 < face.size(); ++i) tx.insert_edge(face[i + 1], m.prev(face[i]));
  return a;
}

void remove_edges_of(Transaction& tx, std::span<const CornerId> corners) {
  std::vector<EdgeId> edges;
  edges.reserve(corners.size());
  for (CornerId c : corners) edges.push_back(tx.mesh().edge(c));
  for (EdgeId e : edges) tx.delete_edge(e);
}

}  // namespace dlfl::detail

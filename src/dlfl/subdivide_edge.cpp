// A vertex on an edge, and its inverse. See Mesh::subdivide_edge and Mesh::unsubdivide_edge in mesh.h.

#include <cmath>

#include <dlfl/errors.h>
#include <dlfl/mesh.h>

namespace dlfl {

VertexId Mesh::subdivide_edge(EdgeId e, const glm::dvec3& position, const detail::Reuse& reuse) {
  require(e, "subdivide_edge");
  if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z)) {
    throw InvalidArgument("subdivide_edge: position for the vertex on " + to_string(e) + " is not finite");
  }
  auto reusable = [](bool alive, std::uint32_t index, std::uint32_t capacity, bool valid) {
    return !valid || (index < capacity && !alive);
  };
  if (!reusable(is_alive(reuse.vertex), reuse.vertex.index(), vertex_capacity(), reuse.vertex.valid()) ||
      !reusable(is_alive(reuse.edge), reuse.edge.index(), edge_capacity(), reuse.edge.valid()) ||
      !reusable(is_alive(reuse.corners[0]), reuse.corners[0].index(), corner_capacity(),
                reuse.corners[0].valid()) ||
      !reusable(is_alive(reuse.corners[1]), reuse.corners[1].index(), corner_capacity(),
                reuse.corners[1].valid()) ||
      (reuse.corners[0].valid() && reuse.corners[0] == reuse.corners[1])) {
    throw InvalidArgument("subdivide_edge: a handle to reuse is not a removed element");
  }
  const CornerId s0 = corner(e, 0);  // at u, side 0 runs u -> w
  const CornerId s1 = corner(e, 1);  // at w
  const CornerId x0 = next(s0);
  const CornerId x1 = next(s1);

  const VertexId m = new_vertex(reuse.vertex);
  const CornerId d0 = new_corner(reuse.corners[0]);  // at m, continues side 0 towards w along the new edge
  const CornerId d1 = new_corner(reuse.corners[1]);  // at m, continues side 1 towards u along e
  const EdgeId e2 = new_edge(reuse.edge);
  positions_[m.index()] = position;
  vertex_corner_[m.index()] = d0;
  corners_[d0.index()] = {m, face(s0), CornerId(), CornerId(), e2};
  corners_[d1.index()] = {m, face(s1), CornerId(), CornerId(), e};
  link(s0, d0);
  link(d0, x0);
  link(s1, d1);
  link(d1, x1);
  corners_[s1.index()].edge = e2;
  edges_[e.index()].corner = {s0, d1};
  edges_[e2.index()].corner = {d0, s1};
  faces_[face(s0).index()].size += 1;
  faces_[face(s1).index()].size += 1;
  apply_anchors(reuse);
  return m;
}

void Mesh::unsubdivide_edge(VertexId v, const detail::Reuse& reuse) {
  require(v, "unsubdivide_edge");
  if (valence(v) != 2) {
    throw TopologyError("unsubdivide_edge: " + to_string(v) + " has valence " + std::to_string(valence(v)) +
                        ", not 2");
  }
  const CornerId a = corner(v);
  const CornerId b = next_around_vertex(a);
  // d0 leaves v on side 0 of the edge that goes away; d1 is where the kept edge arrives at v on its side 0.
  const bool a_leaves = corner(edge(a), 0) == a;
  const bool b_leaves = corner(edge(b), 0) == b;
  if (a_leaves == b_leaves) {
    throw TopologyError("unsubdivide_edge: the edges at " + to_string(v) +
                        " do not continue each other (both " + (a_leaves ? "start" : "end") +
                        " there on side 0)");
  }
  const CornerId d0 = a_leaves ? a : b;
  const CornerId d1 = a_leaves ? b : a;
  const EdgeId kept = edge(d1);
  const EdgeId gone = edge(d0);
  const CornerId s0 = corner(kept, 0);  // at the far end u of the kept edge
  const CornerId s1 = corner(gone, 1);  // at the far end w of the removed edge
  if (vertex(s0) == vertex(s1)) {
    throw TopologyError("unsubdivide_edge: both neighbours of " + to_string(v) + " are " +
                        to_string(vertex(s0)) + "; the joined edge would be a self-loop");
  }
  link(s0, next(d0));
  link(s1, next(d1));
  corners_[s1.index()].edge = kept;
  edges_[kept.index()].corner = {s0, s1};
  for (CornerId d : {d0, d1}) {
    FaceRecord& f = faces_[face(d).index()];
    f.size -= 1;
    if (f.corner == d) f.corner = next(d);
  }
  kill(d0);
  kill(d1);
  kill(gone);
  kill(v);
  apply_anchors(reuse);
}

}  // namespace dlfl

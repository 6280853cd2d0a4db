// A mesh copied into another through the Euler operators, by replaying its teardown backwards.

#include <dlfl/operations/detail/mesh_copy.h>

#include <variant>

#include <dlfl/errors.h>
#include <dlfl/operations/detail/edge_ends.h>
#include <dlfl/operations/detail/shell_copy.h>

namespace dlfl::detail {

CornerId MeshCopy::corner(const Mesh& target, const Mesh& source, CornerId c) const {
  return corner_at(target, edges[source.edge(c).index()], vertices[source.vertex(c).index()]);
}

MeshCopy add_mesh_copy(Transaction& tx, const Mesh& source) {
  MeshCopy copy;
  copy.vertices.assign(source.vertex_capacity(), VertexId());
  copy.edges.assign(source.edge_capacity(), EdgeId());
  Mesh scratch = source;
  // Point spheres stay through the teardown: they are copied as they are.
  for (VertexId v : source.vertices()) {
    if (source.is_point_sphere(v)) copy.vertices[v.index()] = tx.create_vertex(source.position(v));
  }
  ChangeRecord teardown = [&] {
    Transaction t(scratch);
    remove_surface(t);
    return t.commit();
  }();
  const Mesh& target = tx.mesh();
  // Which copy a corner of the scratch stands for: by its vertex and the edge it starts along (there are no
  // self-loops), or the vertex's only corner while it has no edge.
  auto translate = [&](CornerId c) {
    const VertexId v = copy.vertices[scratch.vertex(c).index()];
    const EdgeId e = scratch.edge(c);
    return e.valid() ? corner_at(target, copy.edges[e.index()], v) : target.corner(v);
  };
  for (std::size_t i = teardown.size(); i-- > 0;) {
    const Change change = teardown.inverse(i);
    const Step& step = std::get<Step>(change);
    if (step.kind == Step::Kind::create_vertex) {
      const VertexId made = tx.create_vertex(step.position);
      copy.vertices[scratch.apply(step).vertex.index()] = made;
    } else if (step.kind == Step::Kind::insert_edge) {
      const EdgeId made = tx.insert_edge(translate(step.corner1), translate(step.corner2)).edge;
      copy.edges[scratch.apply(step).edge.index()] = made;
    } else {
      throw TopologyError("add_mesh_copy: unexpected step in the teardown of the source");
    }
  }
  return copy;
}

}  // namespace dlfl::detail

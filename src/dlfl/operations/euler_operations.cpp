// The kernel's Euler operators as registered operations. Their implementation is the kernel's (dlfl/mesh.h);
// this file declares their parameters and outputs once, for the editor, the log and the tool.

#include <dlfl/errors.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl::detail {
namespace {

// Outputs name the handles an operator made or removed; invalid handles are left out.
template <class H>
void put(Params& out, const char* name, H h) {
  if (h.valid()) out[name] = h;
}

glm::dvec3 midpoint(const Mesh& m, EdgeId e) { return 0.5 * (m.position(m.from(e)) + m.position(m.to(e))); }

// An operator that removes one vertex, given as its only parameter (delete_vertex, unsubdivide_edge).
OperationSpec vertex_removal(const char* name, const char* doc, const char* vertex_doc, const char* counts,
                             void (Transaction::*remove)(VertexId)) {
  return edit_operation(name, doc, {param("vertex", ParamType::vertex, vertex_doc)}, counts,
                        [remove](Transaction& tx, const Params& p) {
                          (tx.*remove)(p.handle<VertexId>("vertex"));
                          return Params{};
                        });
}

}  // namespace

std::vector<OperationSpec> euler_operation_specs() {
  std::vector<OperationSpec> ops;

  ops.push_back(edit_operation(
      "create_vertex", "CREATEVERTEX: a new point sphere (one vertex, one face of one corner, no edge)",
      {param("position", ParamType::point, "where the vertex is")}, "V+1, E+0, F+1",
      [](Transaction& tx, const Params& p) {
        return Params{{"vertex", tx.create_vertex(p.point("position"))}};
      }));

  ops.push_back(vertex_removal("delete_vertex", "inverse of CREATEVERTEX: removes a point sphere (no edge)",
                               "the point sphere's vertex", "V-1, E+0, F-1", &Transaction::delete_vertex));

  ops.push_back(edit_operation(
      "insert_edge",
      "INSERTEDGE between the angles of two corners: splits their face, or merges two faces (which joins two "
      "components or adds a handle)",
      {param("corner1", ParamType::corner, "the corner whose angle the edge leaves from"),
       param("corner2", ParamType::corner, "the corner whose angle the edge arrives in")},
      "same face: V+0, E+1, F+1; two faces: V+0, E+1, F-1", [](Transaction& tx, const Params& p) {
        const InsertEdgeResult r =
            tx.insert_edge(p.handle<CornerId>("corner1"), p.handle<CornerId>("corner2"));
        Params out;
        put(out, "edge", r.edge);
        put(out, "created_face", r.created_face);
        put(out, "removed_face", r.removed_face);
        return out;
      }));

  ops.push_back(edit_operation(
      "delete_edge",
      "DELETEEDGE, the inverse of INSERTEDGE: merges the edge's two faces, or splits its one face",
      {param("edge", ParamType::edge, "the edge to remove")},
      "two faces: V+0, E-1, F-1; one face: V+0, E-1, F+1", [](Transaction& tx, const Params& p) {
        const DeleteEdgeResult r = tx.delete_edge(p.handle<EdgeId>("edge"));
        Params out;
        put(out, "created_face", r.created_face);
        put(out, "removed_face", r.removed_face);
        return out;
      }));

  ops.push_back(edit_operation(
      "subdivide_edge", "puts a new vertex on an edge, which becomes two edges",
      {param("edge", ParamType::edge, "the edge to split"),
       param("position", ParamType::point, "where the new vertex is").optional("the edge's midpoint")},
      "V+1, E+1, F+0", [](Transaction& tx, const Params& p) {
        const EdgeId e = p.handle<EdgeId>("edge");
        const glm::dvec3 at = p.has("position") ? p.point("position") : midpoint(tx.mesh(), e);
        return Params{{"vertex", tx.subdivide_edge(e, at)}};
      }));

  ops.push_back(vertex_removal("unsubdivide_edge", "inverse of subdivide_edge: removes a 2-valent vertex",
                               "the 2-valent vertex to remove", "V-1, E-1, F+0",
                               &Transaction::unsubdivide_edge));

  ops.push_back(edit_operation("set_position", "moves a vertex",
                               {param("vertex", ParamType::vertex, "the vertex to move"),
                                param("position", ParamType::point, "its new position")},
                               "V+0, E+0, F+0", [](Transaction& tx, const Params& p) {
                                 tx.set_position(p.handle<VertexId>("vertex"), p.point("position"));
                                 return Params{};
                               }));

  ops.push_back(edit_operation(
      "create_face_manifold",
      "CREATEFACEMANIFOLD: a new two-sided polygon through the points (N create_vertex, then N insert_edge)",
      {param("positions", ParamType::points, "the polygon's corners, at least 2")}, "V+N, E+N, F+2",
      [](Transaction& tx, const Params& p) {
        const FaceManifold fm = tx.create_face_manifold(p.get("positions").as_points());
        return Params{{"front", fm.front}, {"back", fm.back}};
      },
      [](const Mesh&, Params& p) {
        if (p.get("positions").as_points().size() < 2) {
          throw ParameterError("create_face_manifold: parameter positions needs at least 2 points",
                               "positions");
        }
      }));

  return ops;
}

}  // namespace dlfl::detail

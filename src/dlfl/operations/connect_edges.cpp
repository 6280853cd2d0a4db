// connect_edges: the bridge quad between two edges, and its registered operation.

#include <string>

#include <dlfl/errors.h>
#include <dlfl/operations/connect_edges.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

[[noreturn]] void refuse(const char* param, const std::string& what) {
  throw ParameterError(std::string("connect_edges: parameter ") + param + ": " + what, param);
}

void require_corner_with_edge(const Mesh& m, CornerId c, const char* param) {
  if (!m.is_alive(c)) refuse(param, to_string(c) + " is not a live corner");
  if (!m.edge(c).valid())
    refuse(param, to_string(c) + " is a point sphere's corner: it has no edge to bridge");
}

}  // namespace

void check_connect_edges(const Mesh& m, CornerId corner1, CornerId corner2) {
  require_corner_with_edge(m, corner1, "corner1");
  require_corner_with_edge(m, corner2, "corner2");
  if (m.edge(corner1) == m.edge(corner2)) {
    refuse("corner2",
           "its edge " + to_string(m.edge(corner2)) + " is corner1's edge: a bridge needs two edges");
  }
  const FaceId f1 = m.face(corner1), f2 = m.face(corner2);
  if (f1 == f2) {
    refuse("corner2", to_string(corner2) + " lies in face " + to_string(f1) +
                          " with corner1: a bridge joins two faces (in one face it would only cut it)");
  }
  if (m.is_hole(f1) != m.is_hole(f2)) {
    refuse("corner2", "its face " + to_string(f2) + (m.is_hole(f2) ? " is a hole" : " is a surface face") +
                          " and corner1's face " + to_string(f1) +
                          (m.is_hole(f1) ? " is a hole" : " is not") +
                          ": the merged face would be half boundary, half surface (bridge two surface faces "
                          "or two holes)");
  }
  // The quad is c, d, a, b: its new edges are a-d and b-c.
  const VertexId a = m.vertex(corner1), b = m.vertex(m.next(corner1));
  const VertexId c = m.vertex(corner2), d = m.vertex(m.next(corner2));
  if (a == d || b == c) {
    refuse("corner2", "the bridge would join vertex " + to_string(a == d ? a : b) +
                          " to itself (the two edges run through it in opposite directions)");
  }
}

ConnectEdgesResult connect_edges(Transaction& tx, CornerId corner1, CornerId corner2) {
  const Mesh& m = tx.mesh();
  check_connect_edges(m, corner1, corner2);
  const bool holes = m.is_hole(m.face(corner1));
  const CornerId after1 = m.next(corner1), after2 = m.next(corner2);
  ConnectEdgesResult result;
  result.edges[0] = tx.insert_edge(corner1, after2).edge;  // merge: the topology changes here
  // Split: the part from corner2 (c, d, a) plus a new corner at b is the quad.
  result.edges[1] = tx.insert_edge(after1, corner2).edge;
  result.face = m.face(corner2);
  // A split copies the flag of the face it splits: between two holes the quad starts as a hole too.
  if (holes) tx.set_hole(result.face, false);
  return result;
}

std::vector<OperationSpec> detail::connect_edges_operation_specs() {
  return {edit_operation(
      "connect_edges",
      "bridges the edges of two corners in two faces by a quad (two INSERTEDGEs): a handle, or a join",
      {param("corner1", ParamType::corner, "the corner whose edge (a to b) is one side of the bridge"),
       param("corner2", ParamType::corner,
             "the corner, in another face, whose edge (c to d) is the other side; the quad is c, d, a, b")},
      "V+0, E+2, F+0",
      [](Transaction& tx, const Params& p) {
        const ConnectEdgesResult r =
            connect_edges(tx, p.handle<CornerId>("corner1"), p.handle<CornerId>("corner2"));
        return Params{{"edges", std::vector<EdgeId>(r.edges.begin(), r.edges.end())}, {"face", r.face}};
      },
      [](const Mesh& m, Params& p) {
        check_connect_edges(m, p.handle<CornerId>("corner1"), p.handle<CornerId>("corner2"));
      })};
}
}  // namespace dlfl

#include <dlfl/operations/divide_edge.h>

#include <string>

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {
constexpr const char* op_name = "divide_edge";
}  // namespace

void check_divide_edge(const Mesh& m, EdgeId e, std::int64_t segments) {
  detail::require_live(m, op_name, "edge", e);
  if (segments < 1 || segments > max_edge_segments) {
    detail::refuse(op_name, "segments",
                   std::to_string(segments) + " is outside [1, " + std::to_string(max_edge_segments) + "]");
  }
}

DivideEdgeResult divide_edge(Transaction& tx, EdgeId e, std::int64_t segments) {
  const Mesh& m = tx.mesh();
  check_divide_edge(m, e, segments);
  const glm::dvec3 a = m.position(m.from(e));
  const glm::dvec3 b = m.position(m.to(e));
  DivideEdgeResult result;
  result.edges.push_back(e);
  EdgeId rest = e;  // the part still to divide, ending at to(e)
  for (std::int64_t i = 1; i < segments; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(segments);
    const VertexId x = tx.subdivide_edge(rest, (1 - t) * a + t * b);
    // subdivide_edge keeps `rest` up to x; the new edge leaves x on side 0 of the face of rest's side 0.
    rest = m.edge(m.next(m.corner(rest, 0)));
    result.vertices.push_back(x);
    result.edges.push_back(rest);
  }
  return result;
}

std::vector<OperationSpec> detail::divide_edge_operation_specs() {
  return {edit_operation(
      "divide_edge", "cuts an edge into equal segments by new vertices on it",
      {param("edge", ParamType::edge, "the edge to divide"),
       param("segments", ParamType::integer, 2, "the number of edges it becomes; 1 leaves it as it is")
           .in(1, static_cast<double>(max_edge_segments))},
      "V+(s-1), E+(s-1), F+0",
      [](Transaction& tx, const Params& p) {
        const DivideEdgeResult r = divide_edge(tx, p.handle<EdgeId>("edge"), p.integer("segments"));
        return Params{{"vertices", r.vertices}, {"edges", r.edges}};
      },
      [](const Mesh& m, Params& p) {
        check_divide_edge(m, p.handle<EdgeId>("edge"), p.integer("segments"));
      })};
}
}  // namespace dlfl

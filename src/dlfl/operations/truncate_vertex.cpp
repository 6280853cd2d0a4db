// truncate_vertex: the cap cut (detail/cap_cut.h) of one vertex with no inner edge.

#include <dlfl/operations/truncate_vertex.h>

#include <vector>

#include <dlfl/operations/detail/cap_cut.h>
#include <dlfl/operations/detail/handle_selection.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "truncate_vertex";

std::vector<detail::Cap> caps_of(const Mesh& mesh, std::span<const VertexId> vertices,
                                 std::string_view parameter) {
  detail::require_live_list(mesh, op_name, parameter, vertices);
  std::vector<detail::Cap> caps;
  for (VertexId v : vertices) caps.push_back({{v}, {}, 0, to_string(v)});
  return caps;
}

CutResult truncate_all(Transaction& tx, std::span<const VertexId> vertices, const TruncateVertexOptions& o,
                       std::string_view parameter) {
  const auto caps = caps_of(tx.mesh(), vertices, parameter);
  return detail::cut_caps(tx, op_name, parameter, caps, o.offset);
}

}  // namespace

CutResult truncate_vertex(Transaction& tx, VertexId vertex, const TruncateVertexOptions& options) {
  return truncate_all(tx, std::span<const VertexId>(&vertex, 1), options, "vertex");
}

CutResult truncate_vertices(Transaction& tx, std::span<const VertexId> vertices,
                            const TruncateVertexOptions& options) {
  return truncate_all(tx, vertices, options, "vertices");
}

void check_truncate_vertices(const Mesh& mesh, std::span<const VertexId> vertices,
                             const TruncateVertexOptions& options, std::string_view parameter) {
  const auto caps = caps_of(mesh, vertices, parameter);
  detail::check_caps(mesh, op_name, parameter, caps, options.offset);
}

namespace detail {

std::vector<OperationSpec> truncate_vertex_operation_specs() {
  return {edit_operation(
      "truncate_vertex", "cuts a corner off: a vertex of valence k becomes a k-gon",
      {param("vertex", ParamType::vertex, "the vertex to cut off")
           .optional("exactly one of vertex and vertices"),
       param("vertices", ParamType::vertices, "vertices to cut off together")
           .optional("exactly one of vertex and vertices"),
       offset_param()},
      "per vertex of valence k: V+k-1, E+k, F+1",
      [](Transaction& tx, const Params& p) {
        const auto selection = selected_handles<VertexId>(op_name, p, "vertex", "vertices");
        const CutResult cut = truncate_all(tx, selection.handles, {p.number("offset")}, selection.parameter);
        Params out;
        out["faces"] = cut.faces;
        out["vertices"] = cut.vertices;
        if (selection.parameter == "vertex") out["face"] = cut.faces.front();
        return out;
      },
      [](const Mesh& mesh, Params& p) {
        const auto selection = selected_handles<VertexId>(op_name, p, "vertex", "vertices");
        check_truncate_vertices(mesh, selection.handles, {p.number("offset")}, selection.parameter);
      })};
}

}  // namespace detail
}  // namespace dlfl

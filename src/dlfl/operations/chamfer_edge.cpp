// chamfer_edge: the cap cut (detail/cap_cut.h) of the two ends of an edge, the edge inner.

#include <dlfl/operations/chamfer_edge.h>

#include <vector>

#include <dlfl/operations/detail/cap_cut.h>
#include <dlfl/operations/detail/handle_selection.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "chamfer_edge";

std::vector<detail::Cap> caps_of(const Mesh& mesh, std::span<const EdgeId> edges,
                                 std::string_view parameter) {
  detail::require_live_list(mesh, op_name, parameter, edges);
  std::vector<detail::Cap> caps;
  for (EdgeId e : edges) caps.push_back({{mesh.from(e), mesh.to(e)}, {e}, 0, to_string(e)});
  return caps;
}

CutResult chamfer_all(Transaction& tx, std::span<const EdgeId> edges, const ChamferEdgeOptions& o,
                      std::string_view parameter) {
  const auto caps = caps_of(tx.mesh(), edges, parameter);
  return detail::cut_caps(tx, op_name, parameter, caps, o.offset);
}

}  // namespace

CutResult chamfer_edge(Transaction& tx, EdgeId edge, const ChamferEdgeOptions& options) {
  return chamfer_all(tx, std::span<const EdgeId>(&edge, 1), options, "edge");
}

CutResult chamfer_edges(Transaction& tx, std::span<const EdgeId> edges, const ChamferEdgeOptions& options) {
  return chamfer_all(tx, edges, options, "edges");
}

void check_chamfer_edges(const Mesh& mesh, std::span<const EdgeId> edges, const ChamferEdgeOptions& options,
                         std::string_view parameter) {
  const auto caps = caps_of(mesh, edges, parameter);
  detail::check_caps(mesh, op_name, parameter, caps, options.offset);
}

namespace detail {

std::vector<OperationSpec> chamfer_edge_operation_specs() {
  return {edit_operation(
      "chamfer_edge", "an edge becomes a new face: it is cut off with its two ends",
      {param("edge", ParamType::edge, "the edge to chamfer").optional("exactly one of edge and edges"),
       param("edges", ParamType::edges, "edges to chamfer together (no two sharing an end)")
           .optional("exactly one of edge and edges"),
       offset_param()},
      "per edge whose ends have valences a and b: V+a+b-4, E+a+b-3, F+1",
      [](Transaction& tx, const Params& p) {
        const auto selection = selected_handles<EdgeId>(op_name, p, "edge", "edges");
        const CutResult cut = chamfer_all(tx, selection.handles, {p.number("offset")}, selection.parameter);
        Params out;
        out["faces"] = cut.faces;
        out["vertices"] = cut.vertices;
        if (selection.parameter == "edge") out["face"] = cut.faces.front();
        return out;
      },
      [](const Mesh& mesh, Params& p) {
        const auto selection = selected_handles<EdgeId>(op_name, p, "edge", "edges");
        check_chamfer_edges(mesh, selection.handles, {p.number("offset")}, selection.parameter);
      })};
}

}  // namespace detail
}  // namespace dlfl

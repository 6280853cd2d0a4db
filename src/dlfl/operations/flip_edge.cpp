#include <dlfl/operations/flip_edge.h>

#include <string>

#include <dlfl/navigation.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {

constexpr const char* op_name = "flip_edge";

[[noreturn]] void refuse(const std::string& why) { detail::refuse(op_name, "edge", why); }

// The corners at the two new ends: in side 0's face and in side 1's. Forward: the corners after the edge's
// far ends (a, b, x along side 0; b, a, y along side 1). Backward: the corners before its near ends.
std::pair<CornerId, CornerId> new_end_corners(const Mesh& m, EdgeId e, FlipDirection direction) {
  const CornerId s0 = m.corner(e, 0), s1 = m.corner(e, 1);
  if (direction == FlipDirection::forward) return {m.next(m.next(s0)), m.next(m.next(s1))};
  return {m.prev(s0), m.prev(s1)};
}

}  // namespace

void check_flip_edge(const Mesh& m, EdgeId e, FlipDirection direction) {
  detail::require_live(m, op_name, "edge", e);
  const CornerId s0 = m.corner(e, 0);
  const CornerId s1 = m.corner(e, 1);
  const FaceId f0 = m.face(s0);
  const FaceId f1 = m.face(s1);
  if (f0 == f1) refuse(to_string(e) + " has " + to_string(f0) + " on both sides; a flip needs two faces");
  for (FaceId f : {f0, f1}) {
    if (m.is_hole(f)) {
      refuse(to_string(e) + " is on the boundary (hole face " + to_string(f) +
             "); a flip would move the boundary");
    }
    if (m.size(f) < 3) {
      refuse(to_string(f) + " beside " + to_string(e) + " has " + std::to_string(m.size(f)) +
             " sides; a flip needs faces of at least 3");
    }
  }
  const auto [at_x, at_y] = new_end_corners(m, e, direction);
  const VertexId x = m.vertex(at_x);  // the new end in f0
  const VertexId y = m.vertex(at_y);  // the new end in f1
  if (x == y) refuse("the flipped edge would be a self-loop at " + to_string(x));
  for (VertexId end : {m.from(e), m.to(e)}) {
    if (m.valence(end) < 3) {
      refuse(to_string(end) + " has " + std::to_string(m.valence(end)) +
             " edges; the flip would leave it hanging on one");
    }
  }
  if (const EdgeId joined = find_edge(m, x, y); joined.valid()) {
    refuse(to_string(x) + " and " + to_string(y) + " are already joined by " + to_string(joined) +
           "; the flipped edge would double it");
  }
  // Either way, x joins the face that keeps f1's corners and y the one that keeps f0's: neither may be there
  // already.
  if (corner_in_face(m, y, f0).valid()) {
    refuse(to_string(y) + " is on " + to_string(f0) + " already; the face would pass through it twice");
  }
  if (corner_in_face(m, x, f1).valid()) {
    refuse(to_string(x) + " is on " + to_string(f1) + " already; the face would pass through it twice");
  }
}

EdgeId flip_edge(Transaction& tx, EdgeId e, FlipDirection direction) {
  const Mesh& m = tx.mesh();
  check_flip_edge(m, e, direction);
  const auto [at_x, at_y] = new_end_corners(m, e, direction);
  tx.delete_edge(e);                       // the two faces merge; at_x and at_y stay, in the merged face
  return tx.insert_edge(at_x, at_y).edge;  // and split again across x and y
}

namespace detail {
namespace {
FlipDirection direction_of(const Params& p) {
  return p.text("direction") == "backward" ? FlipDirection::backward : FlipDirection::forward;
}
}  // namespace

std::vector<OperationSpec> flip_edge_operation_specs() {
  return {edit_operation(
      "flip_edge",
      "turns an edge inside its two faces: each end moves one step forward along its face (two triangles "
      "a-b-x and b-a-y: ab becomes xy)",
      {param("edge", ParamType::edge, "the edge to flip"),
       param("direction", ParamType::text, "forward",
             "forward: each end one step forward; backward: one step back (undoes a forward flip)")
           .one_of({"forward", "backward"})},
      "V+0, E+0, F+0",
      [](Transaction& tx, const Params& p) {
        return Params{{"edge", flip_edge(tx, p.handle<EdgeId>("edge"), direction_of(p))}};
      },
      [](const Mesh& m, Params& p) { check_flip_edge(m, p.handle<EdgeId>("edge"), direction_of(p)); })};
}

}  // namespace detail
}  // namespace dlfl

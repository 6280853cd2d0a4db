// splice_corners: the checks of collapse_edge, made for the edge (corner1 -> corner2) before it is drawn.
// insert_edge(c1, c2) gives corner n1 at u = vertex(c1), before c2, and n2 at v = vertex(c2), before c1; the
// collapse then pairs n1 with c2 and n2 with c1. So the merged vertex's corners are c1 and c2 (each with its
// new partner) and the other corners of u and v, in faces that do not change, except that the corners' face
// is split in two (same face) or merged with the other (two faces).

#include <dlfl/operations/splice_corners.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <dlfl/navigation.h>
#include <dlfl/operations/collapse_edge.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/operations/detail/vertex_merge.h>

namespace dlfl {
namespace {

constexpr const char* op_name = "splice_corners";

[[noreturn]] void refuse_non_manifold(const std::string& why) {
  detail::refuse(op_name, "corner2", "the result would not be a manifold (" + why + ")");
}

// The corners strictly between `from` and `to` along their face.
std::vector<CornerId> corners_between(const Mesh& m, CornerId from, CornerId to) {
  std::vector<CornerId> out;
  for (CornerId c = m.next(from); c != to; c = m.next(c)) out.push_back(c);
  return out;
}

// The face each corner of u and v will be in once the edge is drawn, as a number: the face's index, but for
// a split, corners on the part from c1 to c2 get `face_capacity()` (the part that is not f itself); for a
// merge, the corners of c2's face get c1's face.
class FaceAfterInsert {
 public:
  FaceAfterInsert(const Mesh& m, CornerId c1, CornerId c2) : m_(m), f1_(m.face(c1)), f2_(m.face(c2)) {
    // The parts matter only when the face keeps a corner at u besides c1 and one at v besides c2: walk it
    // only then.
    if (f1_ == f2_ && visits_twice(m.vertex(c1)) && visits_twice(m.vertex(c2))) {
      part_from_c1_ = corners_between(m, c1, c2);
      part_from_c1_.push_back(c1);
      std::sort(part_from_c1_.begin(), part_from_c1_.end());
    }
  }
  std::uint32_t operator()(CornerId c) const {
    const FaceId f = m_.face(c);
    if (f1_ != f2_) return (f == f2_ ? f1_ : f).index();
    if (f == f1_ && std::binary_search(part_from_c1_.begin(), part_from_c1_.end(), c))
      return m_.face_capacity();
    return f.index();
  }

 private:
  bool visits_twice(VertexId x) const {
    int n = 0;
    for (CornerId c : m_.corners(x)) n += m_.face(c) == f1_;
    return n > 1;
  }
  const Mesh& m_;
  FaceId f1_, f2_;
  std::vector<CornerId> part_from_c1_;
};

SpliceCornersOptions options_of(const Params& p) {
  SpliceCornersOptions options;
  if (p.has("position")) options.position = p.point("position");
  return options;
}

}  // namespace

void check_splice_corners(const Mesh& m, CornerId c1, CornerId c2, const SpliceCornersOptions& options) {
  detail::require_live(m, op_name, "corner1", c1);
  detail::require_live(m, op_name, "corner2", c2);
  if (options.position) detail::require_finite(op_name, "position", *options.position);
  const VertexId u = m.vertex(c1);
  const VertexId v = m.vertex(c2);
  const FaceId f1 = m.face(c1);
  const FaceId f2 = m.face(c2);
  if (u == v) {
    detail::refuse(op_name, "corner2",
                   to_string(c2) + " is at " + to_string(v) + ", as corner1 is; splicing needs two vertices");
  }
  if (f1 != f2 && m.is_hole(f1) != m.is_hole(f2)) {
    detail::refuse(op_name, "corner2",
                   to_string(c2) + " is in " + (m.is_hole(f2) ? "hole" : "surface") + " face " +
                       to_string(f2) + " and corner1 in " + (m.is_hole(f1) ? "hole" : "surface") + " face " +
                       to_string(f1) + "; the merged face would be both");
  }
  if (const EdgeId joined = find_edge(m, u, v); joined.valid()) {
    detail::refuse(op_name, "corner2",
                   to_string(u) + " and " + to_string(v) + " are already joined by " + to_string(joined) +
                       "; the splice would make it a self-loop");
  }

  // Vertices: the new edge's sides are triangles when c2 is two steps from c1 along a common face (or c1 two
  // steps from c2); their middle vertices are the allowed common neighbours.
  const std::vector<VertexId> common = detail::common_neighbours(m, u, v);
  std::vector<VertexId> apexes;
  if (f1 == f2) {
    if (m.next(m.next(c1)) == c2) apexes.push_back(m.vertex(m.next(c1)));
    if (m.next(m.next(c2)) == c1 &&
        std::find(apexes.begin(), apexes.end(), m.vertex(m.next(c2))) == apexes.end())
      apexes.push_back(m.vertex(m.next(c2)));
  }
  const std::string doubled = detail::doubled_edges(common, apexes, "the two vertices");
  if (!doubled.empty()) refuse_non_manifold(doubled);

  // Faces: apart from c1 and c2, no face (as it will be) may keep a corner at u and one at v.
  const FaceAfterInsert face_after(m, c1, c2);
  std::vector<std::uint32_t> at_u;
  for (CornerId c : m.corners(u)) {
    if (c != c1) at_u.push_back(face_after(c));
  }
  std::sort(at_u.begin(), at_u.end());
  for (CornerId c : m.corners(v)) {
    if (c == c2 || !std::binary_search(at_u.begin(), at_u.end(), face_after(c))) continue;
    refuse_non_manifold(to_string(m.face(c)) + " would visit both " + to_string(u) + " and " + to_string(v) +
                        " away from the new edge; it would pass through the merged vertex twice");
  }

  // Boundary: the merged vertex's rotation is c2's face, v's other corners, c1's face, u's other corners.
  std::vector<bool> merged{m.is_hole(f2)};
  detail::append_hole_flags(m, m.next_around_vertex(c2), c2, merged);
  merged.push_back(m.is_hole(f1));
  detail::append_hole_flags(m, m.next_around_vertex(c1), c1, merged);
  const std::size_t runs = detail::hole_runs(merged);
  if (runs > std::max<std::size_t>({1, detail::hole_runs(m, u), detail::hole_runs(m, v)})) {
    refuse_non_manifold("the merged vertex would be on the boundary in " + std::to_string(runs) +
                        " separate places, a pinch");
  }
}

VertexId splice_corners(Transaction& tx, CornerId c1, CornerId c2, const SpliceCornersOptions& options) {
  const Mesh& m = tx.mesh();
  check_splice_corners(m, c1, c2, options);
  const glm::dvec3 position =
      options.position ? *options.position : 0.5 * (m.position(m.vertex(c1)) + m.position(m.vertex(c2)));
  const EdgeId e = tx.insert_edge(c1, c2).edge;  // runs from vertex(c1): that end stays
  CollapseEdgeOptions collapse;
  collapse.position = position;
  return collapse_edge(tx, e, collapse).vertex;
}

std::vector<OperationSpec> detail::splice_corners_operation_specs() {
  return {edit_operation(
      "splice_corners",
      "merges the vertices of two corners into one (vertex(corner1) stays): an edge drawn, then collapsed",
      {param("corner1", ParamType::corner, "the corner whose vertex stays"),
       param("corner2", ParamType::corner, "the corner whose vertex is merged into it"),
       param("position", ParamType::point, "where the merged vertex goes")
           .optional("the midpoint of the two vertices")},
      "one face: V-1, E+0, F+1; two faces: V-1, E+0, F-1",
      [](Transaction& tx, const Params& p) {
        return Params{{"vertex", splice_corners(tx, p.handle<CornerId>("corner1"),
                                                p.handle<CornerId>("corner2"), options_of(p))}};
      },
      [](const Mesh& m, Params& p) {
        check_splice_corners(m, p.handle<CornerId>("corner1"), p.handle<CornerId>("corner2"), options_of(p));
      })};
}
}  // namespace dlfl

// sqrt(3) under the curve boundary rule: Kobbelt's boundary rule, over pairs of steps. See sqrt3.h and
// docs/boundaries.md.

#include <string>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/detail/boundary_curve.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/sqrt3_steps.h>
#include <dlfl/schemes/sqrt3.h>

namespace dlfl::detail {

namespace {

constexpr std::uint32_t none = 0xFFFFFFFFu;

// What becomes of the edge of a surface corner: flipped (both sides are surface faces), kept (a boundary
// edge of a loop this step keeps) or trisected (a boundary edge of a loop this step trisects).
enum class Side : std::uint8_t { inner, kept, trisected };

// The step's reading of the input: the fate of every surface corner's edge, the corner of each surface face
// whose edge is trisected (at most one), and the numbering of the new points.
//
// Notation, for a surface triangle t = (a, b, x) whose corner m at a has its edge a -> b trisected: p1(m),
// p2(m) are the points of that edge at a third of it from a and from b. Every other surface corner c of t
// has one point of t next to its edge, P(c): the face point of t when t has no trisected edge, else p2(m)
// for c = next(m) (the edge b -> x) and p1(m) for c = prev(m) (the edge x -> a). Then t is cut into the fan
// (a, p1, x), (p1, p2, x), (p2, b, x) from x, whose edges x-a and x-b are flipped like any inner edge.
class Plan {
 public:
  Plan(const Mesh& input, const Mesh& m) : m_(m) {
    const auto [nv, ne, nf, nc] = dense_counts(m);
    trisect_ = m.find_attribute<FaceId, bool>(sqrt3_trisect_attribute);
    side_.assign(nc, Side::inner);
    cut_.assign(nf, none);
    for (std::uint32_t e = 0; e < ne; ++e) {
      if (m.is_hole(m.face(EdgeId(e), 0)) && m.is_hole(m.face(EdgeId(e), 1))) {
        throw TopologyError("sqrt3: " + to_string(original_handle<EdgeId>(input, e)) +
                            " has holes on both sides; the boundary rule needs a surface face at every edge");
      }
    }
    for (std::uint32_t k = 0; k < nc; ++k) {
      const CornerId c(k);
      const FaceId across = m.face(m.opposite(c));
      if (m.is_hole(m.face(c)) || !m.is_hole(across)) continue;
      if (!trisected(across)) {
        side_[k] = Side::kept;
        continue;
      }
      side_[k] = Side::trisected;
      const std::uint32_t t = m.face(c).index();
      if (cut_[t] != none) {
        throw TopologyError("sqrt3: " + to_string(original_handle<FaceId>(input, t)) +
                            " has two edges on boundary loops to trisect (attribute " +
                            std::string(sqrt3_trisect_attribute) +
                            "), which one sqrt(3) step cannot make; a step with the loops unmarked can");
      }
      cut_[t] = k;
    }
    // Points: vertex points, then the face points of the faces without a trisected edge, then two points
    // per trisected edge (the one near its from() first).
    std::uint32_t next = nv;
    face_point_.assign(nf, none);
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (!m.is_hole(FaceId(f)) && cut_[f] == none) face_point_[f] = next++;
    }
    third_.assign(ne, none);
    for (std::uint32_t k = 0; k < nc; ++k) {
      if (side_[k] != Side::trisected) continue;
      third_[m.edge(CornerId(k)).index()] = next;
      next += 2;
    }
    num_points_ = next;
  }

  bool trisected(FaceId hole) const { return trisect_ && (*trisect_)[hole]; }
  Side side(CornerId c) const { return side_[c.index()]; }
  std::uint32_t num_points() const { return num_points_; }
  std::uint32_t face_point(FaceId f) const { return face_point_[f.index()]; }
  // The trisected corner of face f, or none.
  std::uint32_t cut(FaceId f) const { return cut_[f.index()]; }

  // p1 and p2 of the trisected corner m: the points of its edge near vertex(m) and near vertex(next m).
  std::uint32_t p1(CornerId m) const { return third_[m_.edge(m).index()] + near_second(m); }
  std::uint32_t p2(CornerId m) const { return third_[m_.edge(m).index()] + 1 - near_second(m); }
  // P(c) for a surface corner whose edge is not trisected.
  std::uint32_t point(CornerId c) const {
    const std::uint32_t m = cut(m_.face(c));
    if (m == none) return face_point(m_.face(c));
    return m_.next(CornerId(m)) == c ? p2(CornerId(m)) : p1(CornerId(m));
  }

 private:
  // Whether vertex(m) is the edge's to(), so that the point near it is the second.
  std::uint32_t near_second(CornerId m) const { return m_.corner(m_.edge(m), 0) == m ? 0 : 1; }

  const Mesh& m_;
  std::optional<ConstAttribute<FaceId, bool>> trisect_;
  std::vector<Side> side_;
  std::vector<std::uint32_t> cut_, face_point_, third_;
  std::uint32_t num_points_ = 0;
};

// Connectivity. Triangle T(c) of surface corner c, output corners L(c) + 0, 1, 2 (L = layout.corner):
//   inner edge:      (a, Q, P) with a = vertex(c), P = P(c), Q = P(opposite c): the flipped edge is Q-P;
//   kept edge:       (a, b, P) with b = vertex(next c): the edge stays;
//   trisected edge:  (p1, p2, x) with x = vertex(prev c): the middle of the fan.
// A kept hole corner h stays one corner (at vertex(h)); a trisected one becomes three: at vertex(h), at
// p2(s) and at p1(s), s = opposite(h) (its edge runs the other way, so p2(s) is the point near vertex(h)).
//
// Twins (each pair found from both sides below):
// - T(c) corner 0 of an inner edge, a -> Q: with o = opposite(c) and m the trisected corner of face(o):
//   without m, Q is a face point and T(next o) corner 2 runs Q -> a; if m = prev(o), Q = p2(m) and a is the
//   apex of m's fan: T(m) corner 1 runs p2 -> a; if m = next(o), Q = p1(m) and a = vertex(m): a -> p1 is a
//   third of the boundary edge, whose hole corner opposite(m) has its corner 2 run p1 -> a.
// - corner 1 of an inner edge, Q -> P: T(opposite c) corner 1.
// - corner 2, P -> a (inner or kept edge): without m in face(c), the corner q = prev(c) gives a -> P: T(q)
//   corner 1 if q's edge is kept, else T(opposite q) corner 0; if c = next(m), P -> a is the last third of
//   m's edge: the hole corner opposite(m), corner 0; if c = prev(m), a is the apex: T(m) corner 2.
// - corner 0 of a kept edge, a -> b: the hole corner opposite(c).
// - corner 1 of a kept edge, b -> P: without m, T(next c) corner 2; if c = next(m), b is the apex: T(m)
//   corner 1; if c = prev(m), b = vertex(m): the hole corner opposite(m), corner 2.
// - T(m) of a trisected edge: corner 0 (p1 -> p2) the hole corner opposite(m), corner 1; corner 1 (p2 -> x)
//   the corner q = next(m) running x -> p2: T(q) corner 1 if q's edge is kept, else T(opposite q) corner 0;
//   corner 2 (x -> p1): T(prev m) corner 2.
void assemble(const Mesh& m, const Plan& plan, const OpenLayout& layout, MeshAssembler& out) {
  const auto nc = static_cast<std::uint32_t>(m.num_corners());
  auto L = [&](CornerId c) { return layout.corner(c); };
  // The output corner running from vertex(next q) to P(q), for a corner q whose edge is not trisected:
  // corner 1 of T(q) = (vertex(q), vertex(next q), P(q)) if the edge is kept, else corner 0 of
  // T(opposite q) = (vertex(next q), P(q), ...).
  auto to_point = [&](CornerId q) { return plan.side(q) == Side::kept ? L(q) + 1 : L(m.opposite(q)) + 0; };
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const FaceId t = m.face(c);
    if (m.is_hole(t)) {
      const CornerId s = m.opposite(c);
      if (!plan.trisected(t)) {
        out.set_corner(L(c), m.vertex(c).index(), L(s) + 0);
        continue;
      }
      out.set_corner(L(c) + 0, m.vertex(c).index(), L(m.next(s)) + 2);
      out.set_corner(L(c) + 1, plan.p2(s), L(s) + 0);
      out.set_corner(L(c) + 2, plan.p1(s), to_point(m.prev(s)));
      continue;
    }
    const std::uint32_t cut = plan.cut(t);
    const std::uint32_t q = L(c);
    if (plan.side(c) == Side::trisected) {
      out.set_corner(q + 0, plan.p1(c), L(m.opposite(c)) + 1);
      out.set_corner(q + 1, plan.p2(c), to_point(m.next(c)));
      out.set_corner(q + 2, m.vertex(m.prev(c)).index(), L(m.prev(c)) + 2);
      continue;
    }
    // Corner 2, P -> a.
    std::uint32_t twin2 = 0;
    if (cut == none) {
      twin2 = to_point(m.prev(c));
    } else if (m.next(CornerId(cut)) == c) {
      twin2 = L(m.opposite(CornerId(cut))) + 0;
    } else {
      twin2 = L(CornerId(cut)) + 2;
    }
    out.set_corner(q + 2, plan.point(c), twin2);
    if (plan.side(c) == Side::kept) {
      std::uint32_t twin1 = 0;
      if (cut == none) {
        twin1 = L(m.next(c)) + 2;
      } else if (m.next(CornerId(cut)) == c) {
        twin1 = L(CornerId(cut)) + 1;
      } else {
        twin1 = L(m.opposite(CornerId(cut))) + 2;
      }
      out.set_corner(q + 0, m.vertex(c).index(), L(m.opposite(c)));
      out.set_corner(q + 1, m.vertex(m.next(c)).index(), twin1);
      continue;
    }
    const CornerId o = m.opposite(c);
    const std::uint32_t cut_o = plan.cut(m.face(o));
    std::uint32_t twin0 = 0;
    if (cut_o == none) {
      twin0 = L(m.next(o)) + 2;
    } else if (m.prev(o) == CornerId(cut_o)) {
      twin0 = L(CornerId(cut_o)) + 1;
    } else {
      twin0 = L(m.opposite(CornerId(cut_o))) + 2;
    }
    out.set_corner(q + 0, m.vertex(c).index(), twin0);
    out.set_corner(q + 1, plan.point(o), L(o) + 1);
  }
  layout.set_hole_flags(out);
}

// Positions: face points at centroids; interior vertices by Kobbelt's rule; boundary vertices of a kept loop
// (and sharp ones) unmoved; on a trisected loop, the ternary cubic B-spline rules: a vertex goes to
// (4, 19, 4) / 27 of its neighbours and itself, the point of an edge a -> b near a to (1, 16, 10) / 27 of
// the neighbour before a, a and b (at a sharp end, the reflections of BoundaryVertices::before and after).
void set_positions(const Mesh& m, const Plan& plan, const BoundaryVertices& boundary, MeshAssembler& out) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (plan.face_point(FaceId(f)) == none) continue;
    glm::dvec3 sum(0.0);
    for (CornerId c : m.corners(FaceId(f))) sum += m.position(m.vertex(c));
    out.set_position(plan.face_point(FaceId(f)), sum / 3.0);
  }
  std::vector<glm::dvec3> sum(nv, glm::dvec3(0.0));
  std::vector<std::uint32_t> valence(nv, 0);
  for (std::uint32_t e = 0; e < ne; ++e) {
    const std::uint32_t a = m.from(EdgeId(e)).index(), b = m.to(EdgeId(e)).index();
    sum[a] += m.position(VertexId(b));
    sum[b] += m.position(VertexId(a));
    ++valence[a];
    ++valence[b];
  }
  set_sqrt3_vertex_points(m, sum, valence, out);
  for (FaceId h : m.faces()) {
    if (!m.is_hole(h)) continue;
    for (CornerId c : m.corners(h)) {
      const std::uint32_t v = m.vertex(c).index();
      const glm::dvec3& a = m.position(VertexId(v));
      const bool moves = plan.trisected(h) && !boundary.is_sharp(v);
      out.set_position(
          v, moves ? (4.0 * boundary.before(m, c) + 19.0 * a + 4.0 * boundary.after(m, c)) / 27.0 : a);
      if (!plan.trisected(h)) continue;
      const CornerId n = m.next(c), s = m.opposite(c);
      const glm::dvec3& b = m.position(m.vertex(n));
      out.set_position(plan.p2(s), (boundary.before(m, c) + 16.0 * a + 10.0 * b) / 27.0);
      out.set_position(plan.p1(s), (10.0 * a + 16.0 * b + boundary.after(m, n)) / 27.0);
    }
  }
}

// Origins: a vertex point <- its vertex, a face point <- its face, a point of a trisected edge <- that edge;
// T(c) <- c, a hole face <- itself; pieces of old edges (flipped, kept, thirds) <- that edge, and every other
// edge, from an old vertex to a new point in a triangle, <- the triangle's corner at that vertex.
void fill_origins(const Mesh& input, const Mesh& m, const Mesh& result, const Plan& plan,
                  const OpenLayout& layout, Origins& origins) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  const InputHandles in(input);
  reset_origins(origins, result);
  in.fill(origins.vertices, {Origin::Kind::vertex});
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (plan.face_point(FaceId(f)) != none) origins.vertices[plan.face_point(FaceId(f))] = in.face(f);
  }
  for (std::uint32_t k = 0; k < nc; ++k) {
    if (plan.side(CornerId(k)) != Side::trisected) continue;
    origins.vertices[plan.p1(CornerId(k))] = origins.vertices[plan.p2(CornerId(k))] =
        in.edge(m.edge(CornerId(k)).index());
  }
  layout.face_origins(m, in, origins);
  // Whether corner k's edge is the trisected one of its face (an edge between an old vertex and a point of
  // that edge is a third of it, not a spoke).
  auto is_cut = [&](CornerId k) { return plan.cut(m.face(k)) == k.index(); };
  auto of_surface = [&](CornerId c, std::uint32_t i) {
    const Origin edge = in.edge(m.edge(c).index());
    const Origin piece_next = in.edge(m.edge(m.next(c)).index()),
                 piece_prev = in.edge(m.edge(m.prev(c)).index());
    switch (plan.side(c)) {
      case Side::inner: {
        const CornerId o = m.opposite(c);
        if (i == 0) {  // a -> Q: a third of the edge after o if that is trisected, else a spoke in face(o)
          return is_cut(m.next(o)) ? in.edge(m.edge(m.next(o)).index()) : in.corner(m.next(o).index());
        }
        if (i == 1) return edge;
        return is_cut(m.prev(c)) ? piece_prev : in.corner(c.index());  // P -> a
      }
      case Side::kept:
        if (i == 0) return edge;
        if (i == 1) return is_cut(m.next(c)) ? piece_next : in.corner(m.next(c).index());  // b -> P
        return is_cut(m.prev(c)) ? piece_prev : in.corner(c.index());                      // P -> a
      case Side::trisected:
        break;
    }
    return i == 0 ? edge : in.corner(m.prev(c).index());
  };
  set_edge_origins(origins, result, layout.edge_origins(m, in, of_surface, {}));
}

}  // namespace

Mesh sqrt3_open(const Mesh& input, const Mesh& m, const BoundaryOptions& boundary,
                const std::optional<ConstAttribute<VertexId, bool>>& marks, Origins* origins) {
  const Plan plan(input, m);
  const BoundaryVertices vertices(m, boundary, marks);
  const OpenLayout layout(m, 3, 0, [&](FaceId h) { return plan.trisected(h) ? 3u : 1u; });
  MeshAssembler out(plan.num_points(), layout.offsets());
  assemble(m, plan, layout, out);
  set_positions(m, plan, vertices, out);
  Mesh result = out.finish();
  // Corners stay sharp by their mark: a step changes their valence. A loop kept now is trisected next.
  carry_sharp_marks(marks, result, static_cast<std::uint32_t>(m.num_vertices()), &vertices);
  std::optional<FaceAttribute<bool>> next;
  for (FaceId h : m.faces()) {
    if (!m.is_hole(h) || plan.trisected(h)) continue;
    if (!next) next = result.add_face_attribute<bool>(sqrt3_trisect_attribute, false);
    (*next)[FaceId(layout.hole_face(h))] = true;
  }
  if (origins) fill_origins(input, m, result, plan, layout, *origins);
  return result;
}

}  // namespace dlfl::detail

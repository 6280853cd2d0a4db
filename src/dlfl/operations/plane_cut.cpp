// plane_cut: subdivide_edge on every crossed edge, then insert_edge between paired crossings inside every
// crossed surface face, then set_hole on the side that goes.

#include <dlfl/operations/plane_cut.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include <dlfl/geometry.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "plane_cut";

struct Plane {
  glm::dvec3 point;
  glm::dvec3 normal;  // unit
};

// The unit normal, scaled first so that a huge but finite normal does not overflow.
Plane checked_plane(const PlaneCutOptions& o) {
  detail::require_finite(op_name, "point", o.point);
  detail::require_finite(op_name, "normal", o.normal);
  const double largest = std::max({std::abs(o.normal.x), std::abs(o.normal.y), std::abs(o.normal.z)});
  if (!(largest > 0.0)) detail::refuse(op_name, "normal", "is zero: a plane needs a direction");
  return {o.point, glm::normalize(o.normal / largest)};
}

// Signed distances of every vertex slot (0 for removed ones) and the tolerance under which a vertex counts
// as on the plane.
struct Distances {
  std::vector<double> of;
  double tolerance = 0.0;
};

Distances distances(const Mesh& m, const Plane& plane) {
  Distances d;
  d.of.assign(m.vertex_capacity(), 0.0);
  double extent = 0.0;
  for (VertexId v : m.vertices()) {
    const glm::dvec3 r = m.position(v) - plane.point;
    const double dist = glm::dot(r, plane.normal);
    if (!std::isfinite(dist) || !std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z))
      detail::refuse(op_name, "point",
                     "the distance of " + to_string(v) + " from the plane would not be finite");
    d.of[v.index()] = dist;
    extent = std::max({extent, std::abs(r.x), std::abs(r.y), std::abs(r.z)});
  }
  d.tolerance = 1e-12 * extent;
  return d;
}

int side_of(double dist, double tolerance) { return dist > tolerance ? 1 : (dist < -tolerance ? -1 : 0); }

// A face's corners from one off the plane, with their sides.
struct FaceWalk {
  std::vector<CornerId> corners;
  std::vector<int> sides;
};

FaceWalk walk_of(const Mesh& m, FaceId f, const std::vector<signed char>& side) {
  FaceWalk w;
  for (CornerId c : m.corners(f)) w.corners.push_back(c);
  const auto start = std::find_if(w.corners.begin(), w.corners.end(),
                                  [&](CornerId c) { return side[m.vertex(c).index()] != 0; });
  if (start == w.corners.end()) return {};
  std::rotate(w.corners.begin(), start, w.corners.end());
  for (CornerId c : w.corners) w.sides.push_back(side[m.vertex(c).index()]);
  return w;
}

// Where the face's boundary meets the plane's line so that a section edge starts there: indices into the
// walk, in its order. A run of corners on the plane between corners on opposite sides is one crossing. With
// `by_reflex_ends`, a run of more than one corner gives its reflex ends instead (where the face goes on
// across the line: one for a run between opposite sides, none or two for a run between corners on one side,
// as in the notch of a U), which is exact for a planar face; without, its first end (for a face that is not
// planar enough for the turns to tell).
std::vector<std::size_t> crossings(const Mesh& m, FaceId f, const FaceWalk& w, bool by_reflex_ends) {
  const glm::dvec3 normal = newell_vector(m, f);
  const auto reflex = [&](CornerId c) {
    const glm::dvec3 p = m.position(m.vertex(c));
    return glm::dot(glm::cross(p - m.position(m.vertex(m.prev(c))), m.position(m.vertex(m.next(c))) - p),
                    normal) < 0.0;
  };
  std::vector<std::size_t> out;
  const std::size_t n = w.corners.size();
  int before = w.sides[0];
  std::size_t run_start = 0;  // 0: no run open (the walk starts off the plane)
  for (std::size_t k = 1; k <= n; ++k) {
    const int s = w.sides[k % n];
    if (s == 0) {
      if (run_start == 0) run_start = k;
      continue;
    }
    if (run_start != 0) {
      const std::size_t first = run_start, last = k - 1;
      if (first == last || !by_reflex_ends) {
        if (s != before) out.push_back(first);
      } else {
        if (reflex(w.corners[first])) out.push_back(first);
        if (reflex(w.corners[last])) out.push_back(last);
      }
    }
    run_start = 0;
    before = s;
  }
  return out;
}

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;  // indices into the walk

// A pairing splits the face into parts on one side each: no two pairs interleave, no pair joins a vertex to
// itself or two corners next to each other, and no part (the corners of a pair's span not inside a nested
// pair, or those inside no pair) has corners on both sides. O(size of the face times pairs).
bool valid_pairing(const Mesh& m, const FaceWalk& w, Pairs pairs) {
  const std::size_t n = w.corners.size();
  for (auto& [a, b] : pairs) {
    if (a > b) std::swap(a, b);
    if (m.vertex(w.corners[a]) == m.vertex(w.corners[b]) || b - a == 1 || (a == 0 && b == n - 1))
      return false;
  }
  for (auto [a, b] : pairs) {
    for (auto [c, d] : pairs) {
      if (a < c && c < b && b < d) return false;
    }
  }
  std::vector<int> seen(pairs.size() + 1, 0);  // per part: bit 1 above, bit 2 below
  for (std::size_t k = 0; k < n; ++k) {
    if (w.sides[k] == 0) continue;
    std::size_t part = pairs.size(), span = n + 1;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const auto [a, b] = pairs[i];
      if (a < k && k < b && b - a < span) {
        part = i;
        span = b - a;
      }
    }
    seen[part] |= w.sides[k] > 0 ? 1 : 2;
  }
  return std::none_of(seen.begin(), seen.end(), [](int s) { return s == 3; });
}

// The section edges of the face, as pairs of walk indices: the crossings paired along the plane's line in
// the face (each piece of the line inside the face joins two consecutive crossings), else consecutive
// crossings along the face, whichever splits the face into parts on one side each first.
Pairs pairing(const Mesh& m, FaceId f, const FaceWalk& w, const Plane& plane) {
  const glm::dvec3 line = glm::cross(plane.normal, face_normal(m, f));
  for (bool by_reflex_ends : {true, false}) {
    const std::vector<std::size_t> xs = crossings(m, f, w, by_reflex_ends);
    const std::size_t k = xs.size();
    if (k < 2 || k % 2 != 0) continue;
    std::vector<Pairs> candidates;
    if (glm::dot(line, line) > 1e-24) {
      std::vector<std::size_t> order = xs;
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return glm::dot(m.position(m.vertex(w.corners[a])), line) <
               glm::dot(m.position(m.vertex(w.corners[b])), line);
      });
      Pairs along;
      for (std::size_t i = 0; i + 1 < k; i += 2) along.emplace_back(order[i], order[i + 1]);
      candidates.push_back(along);
    }
    for (std::size_t shift = 0; shift < 2; ++shift) {
      Pairs around;
      for (std::size_t i = 0; i + 1 < k; i += 2)
        around.emplace_back(xs[(i + shift) % k], xs[(i + 1 + shift) % k]);
      candidates.push_back(around);
    }
    for (const Pairs& p : candidates) {
      if (valid_pairing(m, w, p)) return p;
    }
  }
  return {};
}

PlaneKeep keep_of(const std::string& word) {
  return word == "above" ? PlaneKeep::above : word == "below" ? PlaneKeep::below : PlaneKeep::both;
}

PlaneCutOptions options_of(const Params& p) {
  return {p.point("point"), p.point("normal"), keep_of(p.text("keep"))};
}

}  // namespace

void check_plane_cut(const Mesh& mesh, const PlaneCutOptions& options) {
  distances(mesh, checked_plane(options));
}

PlaneCutResult plane_cut(Transaction& tx, const PlaneCutOptions& options) {
  const Mesh& m = tx.mesh();
  const Plane plane = checked_plane(options);
  const Distances d = distances(m, plane);
  PlaneCutResult result;
  // 1. Split every edge whose ends are strictly on opposite sides where it crosses.
  std::vector<EdgeId> crossed;
  for (EdgeId e : m.edges()) {
    if (side_of(d.of[m.from(e).index()], d.tolerance) * side_of(d.of[m.to(e).index()], d.tolerance) < 0)
      crossed.push_back(e);
  }
  for (EdgeId e : crossed) {
    const VertexId a = m.from(e), b = m.to(e);
    const double t = d.of[a.index()] / (d.of[a.index()] - d.of[b.index()]);
    const glm::dvec3 pa = m.position(a), pb = m.position(b);
    result.vertices.push_back(tx.subdivide_edge(e, pa + t * (pb - pa)));
  }
  std::vector<signed char> side(m.vertex_capacity(), 0);
  for (VertexId v : m.vertices()) {
    if (v.index() < d.of.size())
      side[v.index()] = static_cast<signed char>(side_of(d.of[v.index()], d.tolerance));
  }
  // 2. The section edges, inside each crossed surface face (the parts it splits into are not crossed again).
  const std::uint32_t faces_before = m.face_capacity();
  for (std::uint32_t i = 0; i < faces_before; ++i) {
    const FaceId f(i);
    if (!m.is_alive(f) || m.is_hole(f) || m.size(f) < 2) continue;
    const FaceWalk w = walk_of(m, f, side);
    if (w.corners.empty()) continue;
    for (const auto& [a, b] : pairing(m, f, w, plane)) {
      const CornerId ca = w.corners[a], cb = w.corners[b];
      if (m.face(ca) == m.face(cb)) result.edges.push_back(tx.insert_edge(ca, cb).edge);
    }
  }
  // 3. The side that goes becomes holes.
  if (options.keep != PlaneKeep::both) {
    const int gone = options.keep == PlaneKeep::above ? -1 : 1;
    for (FaceId f : m.faces()) {
      if (m.is_hole(f) || m.size(f) < 2) continue;
      bool on_gone_side = false;
      for (CornerId c : m.corners(f)) on_gone_side = on_gone_side || side[m.vertex(c).index()] == gone;
      if (on_gone_side) {
        tx.set_hole(f, true);
        result.holes.push_back(f);
      }
    }
  }
  return result;
}

std::vector<OperationSpec> detail::plane_cut_operation_specs() {
  return {edit_operation(
      "plane_cut", "cuts the mesh along a plane: crossed edges split, section edges drawn in crossed faces",
      {param("point", ParamType::point, "a point of the plane"),
       param("normal", ParamType::point, "the plane's normal (above is where it points)"),
       param("keep", ParamType::text, "both", "which side stays surface; the other becomes hole faces")
           .one_of({"both", "above", "below"})},
      "for c crossed edges and s section edges: V+c, E+c+s, F+s",
      [](Transaction& tx, const Params& p) {
        const PlaneCutResult cut = plane_cut(tx, options_of(p));
        return Params{{"vertices", cut.vertices}, {"edges", cut.edges}, {"holes", cut.holes}};
      },
      [](const Mesh& mesh, Params& p) { check_plane_cut(mesh, options_of(p)); })};
}
}  // namespace dlfl

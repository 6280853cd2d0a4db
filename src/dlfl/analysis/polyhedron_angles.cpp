#include <dlfl/analysis/polyhedron_angles.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/errors.h>

namespace dlfl {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Accurate for small and large angles alike (acos loses half the digits near 0).
double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The inner loops compare angles through a key that grows with the angle, is cheap (no trigonometry) and
// keeps full relative precision at both ends: up to 90 degrees |q - x|^2 / 4 = sin^2(angle/2), in [0, 1/2];
// beyond it 1 / |q + x|^2 = 1 / (4 cos^2(angle/2)), in [1/2, inf] (|q + x| is exact near 180 degrees, 1 - cos
// is not).
double key_of(const glm::dvec3& q, const glm::dvec3& x) {
  if (glm::dot(q, x) >= 0.0) {
    const glm::dvec3 d = q - x;
    return 0.25 * glm::dot(d, d);
  }
  const glm::dvec3 s = q + x;
  const double s2 = glm::dot(s, s);
  return s2 > 0.0 ? 1.0 / s2 : infinity;
}

double angle_of_key(double key) {
  if (key <= 0.5) return 2.0 * std::asin(std::sqrt(key));
  return std::numbers::pi - 2.0 * std::asin(std::min(1.0, 0.5 / std::sqrt(key)));
}

// One edge of a Gaussian-image polygon: the minor great-circle arc from normal a to the next normal b, or the
// point a alone (the end of an open chain, or a and b equal or exactly opposite, where no arc is defined).
// Only a is kept: b is the start of another arc of the same polygon, so the endpoint pairs are all seen.
// Nothing is normalized here (no square root per arc): the side tests only need signs, and the rare searches
// that need the unit pole divide by |pole| then.
struct Arc {
  glm::dvec3 a{0.0};
  glm::dvec3 pole{0.0};    // normal of the arc's great circle, along a x b
  glm::dvec3 a_side{0.0};  // pole x a: points on the arc's side of a
  glm::dvec3 b_side{0.0};  // b x pole: points on the arc's side of b
  double pole2 = 0.0;      // |pole|^2
  double chord2 = 0.0;     // |a - b|^2
  bool is_point = true;
};

// Fills `arc` (default-constructed: a point) as the arc from a to b.
void make_arc(const glm::dvec3& a, const glm::dvec3& b, Arc& arc) {
  arc.a = a;
  // (a - b) x (a + b) = 2 a x b, but keeps its relative accuracy when a and b are nearly equal or opposite.
  const glm::dvec3 d = a - b;
  const glm::dvec3 pole = glm::cross(d, a + b);
  const double pole2 = glm::dot(pole, pole);
  if (!(pole2 > 0.0 && std::isfinite(pole2))) return;
  arc.pole = pole;
  arc.pole2 = pole2;
  arc.a_side = glm::cross(pole, a);
  arc.b_side = glm::cross(b, pole);
  arc.chord2 = glm::dot(d, d);
  arc.is_point = false;
}

// The key of the largest angle between unit vector q and a point of the arc. The point of the great circle
// farthest from q is x* = -(q - (q.m) m) / |...| (m the unit pole), at pi - asin|q.m| from q; if it lies on
// the arc (q on the far side of both endpoint planes) that is the maximum, else the angle to an endpoint is,
// and only a is checked here (see Arc). In key form |q + x*|^2 = (q.m)^2 + (1 - |q_perp|)^2, with
// 1 - |q_perp| written as (q.m)^2 / (1 + |q_perp|) to stay accurate. When q is the pole every point is at 90
// degrees, and the formula gives that too.
double farthest_key(const glm::dvec3& q, const Arc& arc) {
  if (!arc.is_point && glm::dot(q, arc.a_side) <= 0.0 && glm::dot(q, arc.b_side) <= 0.0) {
    const double h = glm::dot(q, arc.pole);
    const double h2 = h * h / arc.pole2;  // (q.m)^2
    const double perp = std::sqrt(std::max(0.0, 1.0 - h2));
    const double gap = h2 / (1.0 + perp);
    const double s2 = h2 + gap * gap;
    return s2 > 0.0 ? 1.0 / s2 : infinity;
  }
  return key_of(q, arc.a);
}

// Whether arc g holds a point whose antipode lies on arc h. Two minor arcs on different great circles can
// only do so at x = +-(pole_g x pole_h), the circles' crossing points: x on g and -x on h, or the reverse.
// Arcs on one circle (poles parallel) are left out: if they hold an antipodal pair, so does an endpoint.
bool antipodal_arcs(const Arc& g, const Arc& h) {
  if (g.is_point || h.is_point) return false;
  const glm::dvec3 x = glm::cross(g.pole, h.pole);
  if (x == glm::dvec3(0.0)) return false;
  // +1 if the crossing point x lies on the arc, -1 if -x does, 0 if neither.
  const auto on = [&x](const Arc& arc) {
    const double s = glm::dot(x, arc.a_side), t = glm::dot(x, arc.b_side);
    return s >= 0.0 && t >= 0.0 ? 1 : s <= 0.0 && t <= 0.0 ? -1 : 0;
  };
  const int on_g = on(g);
  return on_g != 0 && on(h) == -on_g;
}

// Whether some arc of g and some arc of h (of g itself when h is null) hold antipodal points, given `best`,
// the key of the normals-against-arcs search over the same pair. If x on arc A has its antipode on another
// arc, the farther end of A is at least pi - length(A) / 2 from -x, and that search has seen it: so only arcs
// longer than 2 (pi - best angle) can take part (none when best is at most 90 degrees, the common case). The
// bound is lowered by 1e-9 so that rounding cannot drop an exact tie (the tetrahedron's antipodal arc
// midpoints are one), and compared as chords |a - b|^2 = 4 sin^2(length / 2), which grow with the length.
bool antipodal_pair(const Arc* g, std::size_t ng, const Arc* h, std::size_t nh, double best) {
  if (best <= 0.5) return false;
  const double shortest = 2.0 * (std::numbers::pi - angle_of_key(best)) - 1e-9;
  const double s = std::sin(0.5 * std::max(0.0, shortest));
  const double min_chord2 = 4.0 * s * s;
  const auto may_take_part = [min_chord2](const Arc& arc) {
    return !arc.is_point && arc.chord2 >= min_chord2;
  };
  for (std::size_t i = 0; i < ng; ++i) {
    if (!may_take_part(g[i])) continue;
    const Arc* other = h ? h : g + i + 1;
    const std::size_t count = h ? nh : ng - i - 1;
    for (std::size_t j = 0; j < count; ++j) {
      if (may_take_part(other[j]) && antipodal_arcs(g[i], other[j])) return true;
    }
  }
  return false;
}

// Key of the spherical diameter of one polygon: every normal (the arcs' starts) against every arc, and every
// pair of arcs for antipodal points. Along two arcs p(t).q(s) has critical points with both points inside
// the arcs only where p = +-q (elsewhere p' = +-q' and the Hessian [[-p.q, +-1], [+-1, -p.q]] is a saddle),
// so a widest pair below 180 degrees has a point at a normal, and 180 degrees needs the antipodal test.
double diameter_key(const Arc* g, std::size_t ng) {
  double best = 0.0;
  for (std::size_t i = 0; i < ng && best < infinity; ++i) {
    for (std::size_t j = 0; j < ng; ++j) best = std::max(best, farthest_key(g[i].a, g[j]));
  }
  return best < infinity && antipodal_pair(g, ng, nullptr, 0, best) ? infinity : best;
}

// Key of the largest angle between a point of polygon g and a point of polygon h, by the same argument.
double cross_diameter_key(const Arc* g, std::size_t ng, const Arc* h, std::size_t nh) {
  double best = 0.0;
  for (std::size_t i = 0; i < ng && best < infinity; ++i) {
    for (std::size_t j = 0; j < nh; ++j) best = std::max(best, farthest_key(g[i].a, h[j]));
  }
  for (std::size_t j = 0; j < nh && best < infinity; ++j) {
    for (std::size_t i = 0; i < ng; ++i) best = std::max(best, farthest_key(h[j].a, g[i]));
  }
  return best < infinity && antipodal_pair(g, ng, h, nh, best) ? infinity : best;
}

// Appends the Gaussian-image polygon of v: one arc per corner around v whose face has a normal, to the
// normal of the next face around v (across edge(c)) when that one has a normal too, else a point (the end of
// an open chain). `normal(f)` is zero for faces without one (holes, zero area). One walk around v; the arcs
// are filled in place (this runs for every vertex of every face).
template <class Normal>
void append_polygon(const Mesh& mesh, VertexId v, const Normal& normal, std::vector<Arc>& out) {
  if (mesh.is_point_sphere(v)) return;
  const glm::dvec3 none(0.0);
  glm::dvec3 previous = none;
  for (CornerId c : mesh.corners(v)) {
    const glm::dvec3 n = normal(mesh.face(c));
    if (n != none) {
      if (previous != none) make_arc(previous, n, out.back());  // previous's point becomes the arc to n
      out.emplace_back().a = n;
    }
    previous = n;
  }
  // Close the turn: the last face's arc runs to the first face's normal when both have one.
  const glm::dvec3 start = normal(mesh.face(mesh.corner(v)));
  if (previous != none && start != none) make_arc(previous, start, out.back());
}

// The polygons of a face's vertices, one after the other: polygon i is arcs[start[i], start[i + 1]).
struct FacePolygons {
  std::vector<Arc> arcs;
  std::vector<std::size_t> start;
  std::vector<VertexId> vertex;
  std::vector<EdgeId> edge;  // edge[i] joins vertex[i] and vertex[i + 1] (cyclically)

  template <class Normal>
  void build(const Mesh& mesh, FaceId f, const Normal& normal) {
    arcs.clear();
    start.assign(1, 0);
    vertex.clear();
    edge.clear();
    for (CornerId c : mesh.corners(f)) {
      vertex.push_back(mesh.vertex(c));
      edge.push_back(mesh.edge(c));
      append_polygon(mesh, mesh.vertex(c), normal, arcs);
      start.push_back(arcs.size());
    }
  }
  const Arc* arcs_of(std::size_t i) const { return arcs.data() + start[i]; }
  std::size_t size_of(std::size_t i) const { return start[i + 1] - start[i]; }
};

// Key of the face angle: the largest cached vertex key, and the cross diameter of every pair of different
// vertices. `pair_key(i, j, compute)` may answer from a cache (polyhedron_angles keeps one per edge).
template <class VertexKey, class PairKey>
double face_key(const FacePolygons& p, const VertexKey& vertex_key, const PairKey& pair_key) {
  const std::size_t n = p.vertex.size();
  double best = 0.0;
  for (std::size_t i = 0; i < n; ++i) best = std::max(best, vertex_key(i));
  for (std::size_t i = 0; i < n && best < infinity; ++i) {
    for (std::size_t j = i + 1; j < n && best < infinity; ++j) {
      if (p.vertex[i] == p.vertex[j]) continue;  // a face through v twice: v's own diameter is already in
      best = std::max(best, pair_key(i, j, [&] {
                        return cross_diameter_key(p.arcs_of(i), p.size_of(i), p.arcs_of(j), p.size_of(j));
                      }));
    }
  }
  return best;
}

// Unit outward normal, or zero for a hole or a face of zero area (no supporting plane to speak of).
glm::dvec3 usable_normal(const Mesh& mesh, FaceId f) {
  return mesh.is_hole(f) ? glm::dvec3(0.0) : face_plane(mesh, f).normal;
}

void add(AngleSummary& s, double angle) {
  s.max = std::max(s.max, angle);
  s.mean += angle;  // the sum until `finish`
  ++s.count;
}

void finish(AngleSummary& s) { s.mean = s.count ? s.mean / double(s.count) : 0.0; }

}  // namespace

double edge_angle(const Mesh& mesh, EdgeId e) {
  for (int side : {0, 1}) {
    if (mesh.is_hole(mesh.face(e, side))) {
      throw TopologyError("edge_angle: " + to_string(e) + " has a hole face (" +
                          to_string(mesh.face(e, side)) + ") on side " + std::to_string(side));
    }
  }
  return angle_between(face_plane(mesh, mesh.face(e, 0)).normal, face_plane(mesh, mesh.face(e, 1)).normal);
}

double vertex_angle(const Mesh& mesh, VertexId v) {
  const auto normal = [&mesh](FaceId f) { return usable_normal(mesh, f); };
  std::vector<Arc> arcs;
  append_polygon(mesh, v, normal, arcs);
  return angle_of_key(diameter_key(arcs.data(), arcs.size()));
}

double face_angle(const Mesh& mesh, FaceId f) {
  if (mesh.is_hole(f)) throw TopologyError("face_angle: " + to_string(f) + " is a hole face");
  const auto normal = [&mesh](FaceId g) { return usable_normal(mesh, g); };
  FacePolygons p;
  p.build(mesh, f, normal);
  const auto vertex_key = [&p](std::size_t i) { return diameter_key(p.arcs_of(i), p.size_of(i)); };
  const auto pair_key = [](std::size_t, std::size_t, const auto& compute) { return compute(); };
  return angle_of_key(face_key(p, vertex_key, pair_key));
}

PolyhedronAngles polyhedron_angles(const Mesh& mesh) {
  std::vector<glm::dvec3> normals(mesh.face_capacity(), glm::dvec3(0.0));
  for (FaceId f : mesh.faces()) normals[f.index()] = usable_normal(mesh, f);
  const auto normal = [&normals](FaceId f) { return normals[f.index()]; };
  PolyhedronAngles a;
  for (EdgeId e : mesh.edges()) {
    if (!mesh.is_hole(mesh.face(e, 0)) && !mesh.is_hole(mesh.face(e, 1))) {
      add(a.edge, angle_between(normal(mesh.face(e, 0)), normal(mesh.face(e, 1))));
    }
  }
  // Vertex diameters once, reused by every face around the vertex.
  std::vector<double> vertex_keys(mesh.vertex_capacity(), 0.0);
  std::vector<Arc> arcs;  // reused: no allocation per element
  for (VertexId v : mesh.vertices()) {
    if (mesh.is_point_sphere(v)) continue;
    arcs.clear();
    append_polygon(mesh, v, normal, arcs);
    vertex_keys[v.index()] = diameter_key(arcs.data(), arcs.size());
    add(a.vertex, angle_of_key(vertex_keys[v.index()]));
  }
  // The cross diameter of the two ends of an edge is needed by both faces of the edge: computed once.
  std::vector<double> edge_keys(mesh.edge_capacity(), -1.0);
  FacePolygons p;
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f) || mesh.size(f) <= 1) continue;
    p.build(mesh, f, normal);
    const std::size_t n = p.vertex.size();
    const auto vertex_key = [&](std::size_t i) { return vertex_keys[p.vertex[i].index()]; };
    const auto pair_key = [&](std::size_t i, std::size_t j, const auto& compute) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (!adjacent) return compute();
      double& cached = edge_keys[p.edge[j == i + 1 ? i : j].index()];
      if (cached < 0.0) cached = compute();
      return cached;
    };
    add(a.face, angle_of_key(face_key(p, vertex_key, pair_key)));
  }
  finish(a.edge);
  finish(a.vertex);
  finish(a.face);
  return a;
}

}  // namespace dlfl

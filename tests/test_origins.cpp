// Origin maps: for every scheme, on meshes with and without tombstones, every output element names a live
// input element of the kind the scheme's header gives, the counts of each kind are the closed-form ones, the
// geometry agrees (an element from an input element sits where the scheme's rule puts it for that element),
// and per-element data carried across by the origins lands where it should.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/build_mesh.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/doo_sabin.h>
#include <dlfl/schemes/dual.h>
#include <dlfl/schemes/dual_honeycomb_dual.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/loop.h>
#include <dlfl/schemes/meng_prautzsch_honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>
#include <dlfl/schemes/meng_prautzsch_pushing.h>
#include <dlfl/schemes/mlca_polygons.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/schemes/sqrt3.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include "open_meshes.h"
#include "triangle_meshes.h"

using namespace dlfl;
using test::close;

namespace {

using Kind = Origin::Kind;
using Scheme = std::function<Mesh(const Mesh&, Origins*)>;

// ---- helpers
// ------------------------------------------------------------------------------------------------

bool alive_in(const Mesh& in, const Origin& o) {
  switch (o.kind) {
    case Kind::vertex:
      return in.is_alive(VertexId(o.index));
    case Kind::edge:
      return in.is_alive(EdgeId(o.index));
    case Kind::face:
      return in.is_alive(FaceId(o.index));
    case Kind::corner:
      return in.is_alive(CornerId(o.index));
    case Kind::none:
      break;
  }
  return false;
}

// Every slot of the output's capacity: a live element has an origin, alive in the input; a tombstone none.
// Run before the checks that read the input at the origins.
template <class H>
void check_table(const Mesh& in, const Mesh& out, const std::vector<Origin>& table, std::uint32_t capacity) {
  REQUIRE(table.size() == capacity);
  for (std::uint32_t i = 0; i < capacity; ++i) {
    CAPTURE(i);
    if (out.is_alive(H(i))) {
      REQUIRE(alive_in(in, table[i]));  // the checks that follow read the input at the origin
    } else {
      CHECK(table[i].kind == Kind::none);
    }
  }
}

void check_well_formed(const Mesh& in, const Mesh& out, const Origins& o) {
  check_table<VertexId>(in, out, o.vertices, out.vertex_capacity());
  check_table<EdgeId>(in, out, o.edges, out.edge_capacity());
  check_table<FaceId>(in, out, o.faces, out.face_capacity());
}

struct Counts {
  std::size_t vertex = 0, edge = 0, face = 0, corner = 0;
  friend bool operator==(const Counts&, const Counts&) = default;
};

doctest::String to_string_counts(const Counts& c) {
  return ("{vertex " + std::to_string(c.vertex) + ", edge " + std::to_string(c.edge) + ", face " +
          std::to_string(c.face) + ", corner " + std::to_string(c.corner) + "}")
      .c_str();
}

Counts count(const std::vector<Origin>& table) {
  Counts c;
  for (const Origin& o : table) {
    c.vertex += o.kind == Kind::vertex;
    c.edge += o.kind == Kind::edge;
    c.face += o.kind == Kind::face;
    c.corner += o.kind == Kind::corner;
  }
  return c;
}

void check_counts(const Origins& o, const Counts& vertices, const Counts& edges, const Counts& faces) {
  INFO("vertices ", to_string_counts(count(o.vertices)), " edges ", to_string_counts(count(o.edges)),
       " faces ", to_string_counts(count(o.faces)));
  CHECK(count(o.vertices) == vertices);
  CHECK(count(o.edges) == edges);
  CHECK(count(o.faces) == faces);
}

// A sortable key, for comparing sets of origins.
std::pair<int, std::uint32_t> key(const Origin& o) { return {int(o.kind), o.index}; }

std::vector<std::pair<int, std::uint32_t>> sorted_keys(std::vector<Origin> list) {
  std::vector<std::pair<int, std::uint32_t>> keys;
  for (const Origin& o : list) keys.push_back(key(o));
  std::sort(keys.begin(), keys.end());
  return keys;
}

bool same_set(const std::vector<Origin>& a, const std::vector<Origin>& b) {
  return sorted_keys(a) == sorted_keys(b);
}

// The same cyclic sequence, up to rotation.
bool same_cycle(const std::vector<Origin>& a, const std::vector<Origin>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t shift = 0; shift < a.size(); ++shift) {
    bool equal = true;
    for (std::size_t i = 0; i < a.size() && equal; ++i) equal = a[(i + shift) % a.size()] == b[i];
    if (equal) return true;
  }
  return a.empty();
}

// The origins of the vertices of an output face, from its first corner, and of an output edge's two ends.
std::vector<Origin> face_vertex_origins(const Mesh& out, const Origins& o, FaceId f) {
  std::vector<Origin> list;
  for (CornerId c : out.corners(f)) list.push_back(o.of(out.vertex(c)));
  return list;
}
std::vector<Origin> edge_end_origins(const Mesh& out, const Origins& o, EdgeId e) {
  return {o.of(out.from(e)), o.of(out.to(e))};
}

// Output elements by origin.
template <class H>
std::map<std::pair<int, std::uint32_t>, std::vector<H>> by_origin(const std::vector<Origin>& table) {
  std::map<std::pair<int, std::uint32_t>, std::vector<H>> m;
  for (std::uint32_t i = 0; i < table.size(); ++i) {
    if (table[i].kind != Kind::none) m[key(table[i])].push_back(H(i));
  }
  return m;
}

glm::dvec3 centroid_of(const Mesh& m, FaceId f) { return test::centroid(m, f); }

glm::dvec3 face_normal(const Mesh& m, FaceId f) {
  glm::dvec3 n(0.0);
  const glm::dvec3 p0 = m.position(m.vertex(m.first_corner(f)));
  for (CornerId c : m.corners(f)) {
    n += glm::cross(m.position(m.vertex(c)) - p0, m.position(m.vertex(m.next(c))) - p0);
  }
  return glm::normalize(n);
}

// The soup as a mesh whose first vertex, an edge and some faces and corners are tombstones, so that its live
// handles differ from their compacted indices: an extra first vertex (a point sphere) deleted, and the first
// edge between two surface faces deleted and inserted again between the same corners of the merged face.
// Same surface as the soup.
Mesh with_tombstones(const PolygonSoup& soup) {
  PolygonSoup shifted = soup;
  shifted.positions.insert(shifted.positions.begin(), glm::dvec3(100, 100, 100));
  for (auto& i : shifted.indices) ++i;
  Mesh m = build_mesh(shifted);
  m.delete_vertex(VertexId(0));
  EdgeId inner(0);  // the first edge between two surface faces (edge 0 on a closed mesh)
  while (m.is_hole(m.face(inner, 0)) || m.is_hole(m.face(inner, 1))) inner = EdgeId(inner.index() + 1);
  const VertexId a = m.from(inner), b = m.to(inner);
  m.delete_edge(inner);
  for (CornerId ca : m.corners(a)) {
    for (CornerId cb : m.corners(b)) {
      if (m.face(ca) == m.face(cb)) {
        m.insert_edge(ca, cb);
        return m;
      }
    }
  }
  FAIL("no face holds both ends of the deleted edge");
  return m;
}

Origin mapped(const Origin& o, const Mesh::CompactMap& map) {
  switch (o.kind) {
    case Kind::vertex:
      return origin_of(map.vertices[o.index]);
    case Kind::edge:
      return origin_of(map.edges[o.index]);
    case Kind::face:
      return origin_of(map.faces[o.index]);
    case Kind::corner:
      return origin_of(map.corners[o.index]);
    case Kind::none:
      break;
  }
  return {};
}

// On a mesh with tombstones: the origins name the mesh's own handles, which compacting renames exactly as it
// renames the mesh (and the step gives the same result as on the compacted copy). Without origins the step
// gives the same mesh.
void check_tombstones_renamed(const PolygonSoup& soup, const Scheme& scheme) {
  const Mesh holey = with_tombstones(soup);
  Mesh dense = holey;
  const Mesh::CompactMap map = dense.compact();
  // The renaming is not the identity for any kind, so a scheme that named compacted handles would fail.
  REQUIRE(map.vertices[1] == VertexId(0));
  std::uint32_t moved_edges = 0, moved_faces = 0, moved_corners = 0;
  for (std::uint32_t e = 0; e < map.edges.size(); ++e)
    moved_edges += map.edges[e].valid() && map.edges[e] != EdgeId(e);
  REQUIRE(moved_edges > 0);
  for (std::uint32_t f = 0; f < map.faces.size(); ++f)
    moved_faces += map.faces[f].valid() && map.faces[f] != FaceId(f);
  for (std::uint32_t c = 0; c < map.corners.size(); ++c) {
    moved_corners += map.corners[c].valid() && map.corners[c] != CornerId(c);
  }
  REQUIRE(moved_faces > 0);
  REQUIRE(moved_corners > 0);
  Origins from_holey, from_dense;
  const Mesh a = scheme(holey, &from_holey);
  const Mesh b = scheme(dense, &from_dense);
  CHECK(a == b);
  CHECK(scheme(holey, nullptr) == a);
  check_well_formed(holey, a, from_holey);
  REQUIRE(from_holey.vertices.size() == from_dense.vertices.size());
  REQUIRE(from_holey.edges.size() == from_dense.edges.size());
  REQUIRE(from_holey.faces.size() == from_dense.faces.size());
  for (std::size_t i = 0; i < from_holey.vertices.size(); ++i) {
    CHECK(mapped(from_holey.vertices[i], map) == from_dense.vertices[i]);
  }
  for (std::size_t i = 0; i < from_holey.edges.size(); ++i) {
    CHECK(mapped(from_holey.edges[i], map) == from_dense.edges[i]);
  }
  for (std::size_t i = 0; i < from_holey.faces.size(); ++i) {
    CHECK(mapped(from_holey.faces[i], map) == from_dense.faces[i]);
  }
}

// One step with origins: the same mesh as the step without them, with a well-formed table.
Mesh checked_step(const Mesh& in, const Scheme& scheme, Origins& o) {
  Mesh out = scheme(in, &o);
  CHECK(out == scheme(in, nullptr));
  check_well_formed(in, out, o);
  return out;
}

// The same for a scheme with parameters.
template <class Params>
Mesh checked_step(const Mesh& in, Mesh (*scheme)(const Mesh&, const Params&, Origins*), const Params& params,
                  Origins& o) {
  return checked_step(
      in, [&](const Mesh& m, Origins* origins) { return scheme(m, params, origins); }, o);
}

// An output edge from input edge `old`, one half of it: between an end of `old` and `old`'s own point.
bool is_half_of(const Mesh& in, const std::vector<Origin>& ends, EdgeId old) {
  return same_set(ends, {origin_of(in.from(old)), origin_of(old)}) ||
         same_set(ends, {origin_of(in.to(old)), origin_of(old)});
}

// Every output edge stems from an input edge, as a half of it, or from an input corner c, between the
// points that `ends_of_corner(c)` names.
template <class EndsOfCorner>
void check_halves_and_corner_edges(const Mesh& in, const Mesh& out, const Origins& o,
                                   const EndsOfCorner& ends_of_corner) {
  for (EdgeId e : out.edges()) {
    const Origin src = o.of(e);
    const auto ends = edge_end_origins(out, o, e);
    if (src.kind == Kind::edge) {
      CHECK(is_half_of(in, ends, src.edge()));
    } else {
      CHECK(same_set(ends, ends_of_corner(src.corner())));
    }
  }
}

// The parameters of an H or P step with the given tau.
template <class StepParams>
StepParams step_params(double tau) {
  StepParams p;
  p.tau = tau;
  return p;
}

// Closed-form sizes of the input.
struct Sizes {
  std::size_t V, E, F, C;
};
Sizes sizes(const Mesh& m) { return {m.num_vertices(), m.num_edges(), m.num_faces(), m.num_corners()}; }

// ---- per-scheme rules
// ---------------------------------------------------------------------------------------

// The rule that splits hole faces too (boundary=hole); check_open_catmull_clark has the curve rule's.
void check_catmull_clark(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return catmull_clark(m, {BoundaryRule::hole}, origins); }, o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {V, E, F, 0}, {0, 2 * E, 0, C}, {0, 0, 0, C});
  // Positions: face points at centroids, edge points (a + b + F0 + F1) / 4, vertex points (Q + 2R + (n-3)S) /
  // n.
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    glm::dvec3 expected(0.0);
    if (src.kind == Kind::face) {
      expected = centroid_of(in, src.face());
    } else if (src.kind == Kind::edge) {
      const EdgeId e = src.edge();
      expected = (in.position(in.from(e)) + in.position(in.to(e)) + centroid_of(in, in.face(e, 0)) +
                  centroid_of(in, in.face(e, 1))) /
                 4.0;
    } else {
      const VertexId v = src.vertex();
      glm::dvec3 q(0.0), r(0.0);
      double n = 0;
      for (CornerId c : in.corners(v)) {
        q += centroid_of(in, in.face(c));
        r += 0.5 * (in.position(v) + in.position(in.vertex(in.next(c))));
        ++n;
      }
      expected = (q / n + 2.0 * r / n + (n - 3.0) * in.position(v)) / n;
    }
    CHECK(close(out.position(w), expected, 1e-12));
  }
  // Quad of corner c: (vertex point, edge point of edge(c), face point, edge point of edge(prev c)).
  for (FaceId f : out.faces()) {
    const CornerId c = o.of(f).corner();
    CHECK(face_vertex_origins(out, o, f) == std::vector<Origin>{origin_of(in.vertex(c)),
                                                                origin_of(in.edge(c)), origin_of(in.face(c)),
                                                                origin_of(in.edge(in.prev(c)))});
    CHECK(out.is_hole(f) == in.is_hole(in.face(c)));
  }
  check_halves_and_corner_edges(in, out, o, [&](CornerId c) {
    return std::vector<Origin>{origin_of(in.edge(c)), origin_of(in.face(c))};
  });
}

// The Doo-Sabin point of corner c, from the paper's weights.
glm::dvec3 doo_sabin_point(const Mesh& in, CornerId c) {
  const double n = in.size(in.face(c));
  glm::dvec3 p(0.0);
  CornerId x = c;
  for (int k = 0; k < int(n); ++k, x = in.next(x)) {
    const double alpha =
        k == 0 ? 0.25 + 5.0 / (4.0 * n) : (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * k / n)) / (4.0 * n);
    p += alpha * in.position(in.vertex(x));
  }
  return p;
}

// Under boundary=hole, the rule these checks describe (on a closed mesh both rules agree).
constexpr BoundaryOptions hole_rule{BoundaryRule::hole};

void check_doo_sabin(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return doo_sabin(m, hole_rule, origins); }, o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {0, 0, 0, C}, {0, C, 0, C}, {V, E, F, 0});
  for (VertexId w : out.vertices())
    CHECK(close(out.position(w), doo_sabin_point(in, o.of(w).corner()), 1e-12));
  for (FaceId f : out.faces()) {
    const Origin src = o.of(f);
    const auto corners = face_vertex_origins(out, o, f);
    std::vector<Origin> expected;
    if (src.kind == Kind::face) {  // an F-face: the points of its corners, in order, of the face's size
      for (CornerId c : in.corners(src.face())) expected.push_back(origin_of(c));
      CHECK(corners == expected);
      CHECK(out.is_hole(f) == in.is_hole(src.face()));
    } else if (src.kind == Kind::edge) {  // an E-face: the four points at the edge's ends, on its two sides
      const CornerId c0 = in.corner(src.edge(), 0), c1 = in.corner(src.edge(), 1);
      CHECK(
          same_set(corners, {origin_of(c0), origin_of(in.next(c0)), origin_of(c1), origin_of(in.next(c1))}));
    } else {  // a V-face: one point per corner at the vertex, so valence corners
      for (CornerId c : in.corners(src.vertex())) expected.push_back(origin_of(c));
      CHECK(corners.size() == in.valence(src.vertex()));
      CHECK(same_set(corners, expected));
    }
  }
  for (EdgeId e : out.edges()) {
    const Origin src = o.of(e);
    const auto ends = edge_end_origins(out, o, e);
    if (src.kind == Kind::corner) {  // an F-face side along edge(c)
      CHECK(same_set(ends, {src, origin_of(in.next(src.corner()))}));
    } else {  // a V-face side: two corners at one end of the edge, on either side of it
      const EdgeId old = src.edge();
      const CornerId x = ends[0].corner(), y = ends[1].corner();
      CHECK(in.vertex(x) == in.vertex(y));
      CHECK((in.vertex(x) == in.from(old) || in.vertex(x) == in.to(old)));
      for (CornerId z : {x, y}) CHECK((in.edge(z) == old || in.edge(in.prev(z)) == old));
    }
  }
}

// The honeycomb's formula (2) for the point of corner c, with a constant tension a.
glm::dvec3 honeycomb_point(const Mesh& in, CornerId c, double t, double a) {
  std::vector<glm::dvec3> edge_points;
  for (CornerId x = c;;) {
    edge_points.push_back((1 - t) * in.position(in.vertex(x)) + t * in.position(in.vertex(in.next(x))));
    x = in.next(x);
    if (x == c) break;
  }
  const double N = double(edge_points.size());
  glm::dvec3 p = a * edge_points[0];
  for (std::size_t k = 1; k < edge_points.size(); ++k) {
    p += (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * double(k) / N)) * (1 - a) / (3 * N - 5) *
         edge_points[k];
  }
  return p;
}

void check_honeycomb_origins(const Mesh& in, const Mesh& out, const Origins& o) {
  check_well_formed(in, out, o);
  const auto [V, E, F, C] = sizes(in);
  std::size_t P = 0;  // point spheres
  for (VertexId v : in.vertices()) P += in.is_point_sphere(v);
  check_counts(o, {P, 0, 0, C - P}, {0, E, 0, C - P}, {V, 0, F - P, 0});
  for (FaceId f : out.faces()) {
    const Origin src = o.of(f);
    const auto corners = face_vertex_origins(out, o, f);
    if (src.kind == Kind::face) {  // the front face: the points of the face's corners, from its first
      std::vector<Origin> expected;
      for (CornerId c : in.corners(src.face())) expected.push_back(origin_of(c));
      CHECK(corners == expected);
      CHECK(out.is_hole(f) == in.is_hole(src.face()));
      continue;
    }
    const VertexId v = src.vertex();
    if (in.is_point_sphere(v)) {
      CHECK(corners == std::vector<Origin>{src});
      continue;
    }
    // The face around v: the points of the corners at v and of the corners before them, 2 x valence.
    CHECK(corners.size() == 2 * in.valence(v));
    std::vector<Origin> expected;
    for (CornerId c : in.corners(v)) {
      expected.push_back(origin_of(c));
      expected.push_back(origin_of(in.prev(c)));
    }
    CHECK(same_set(corners, expected));
  }
  for (EdgeId e : out.edges()) {
    const Origin src = o.of(e);
    const auto ends = edge_end_origins(out, o, e);
    if (src.kind == Kind::edge) {  // inserted across the edge: joins the points of its two sides
      CHECK(same_set(ends, {origin_of(in.corner(src.edge(), 0)), origin_of(in.corner(src.edge(), 1))}));
    } else {  // the front side that cuts off corner x
      CHECK(same_set(ends, {origin_of(in.prev(src.corner())), src}));
    }
  }
  for (VertexId w : out.vertices()) {
    if (o.of(w).kind == Kind::vertex) CHECK(out.position(w) == in.position(o.of(w).vertex()));
  }
}

void check_honeycomb(const Mesh& in) {
  HoneycombParams p;
  p.t = 0.3;
  p.a = 0.6;
  p.boundary = hole_rule;
  Origins o;
  const Mesh out = honeycomb(in, p, &o);
  CHECK(out == honeycomb(in, p));
  check_honeycomb_origins(in, out, o);
  for (VertexId w : out.vertices()) {
    if (o.of(w).kind == Kind::corner)
      CHECK(close(out.position(w), honeycomb_point(in, o.of(w).corner(), 0.3, 0.6), 1e-12));
  }
  // Zhang-Wang has the honeycomb's topology and handles, so the same origins.
  Origins zw;
  ZhangWangParams zp;
  zp.boundary = hole_rule;
  const Mesh z = zhang_wang_honeycomb(in, zp, &zw);
  CHECK(zw.vertices == o.vertices);
  CHECK(zw.edges == o.edges);
  CHECK(zw.faces == o.faces);
  CHECK(z.num_faces() == out.num_faces());
}

void check_loop(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return loop(m, origins); }, o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {V, E, 0, 0}, {0, 2 * E, 0, C}, {0, 0, F, C});
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    glm::dvec3 expected;
    if (src.kind == Kind::edge) {
      const CornerId s0 = in.corner(src.edge(), 0), s1 = in.corner(src.edge(), 1);
      expected = 0.375 * (in.position(in.vertex(s0)) + in.position(in.vertex(s1))) +
                 0.125 * (in.position(in.vertex(in.prev(s0))) + in.position(in.vertex(in.prev(s1))));
    } else {
      const VertexId v = src.vertex();
      const double n = in.valence(v), beta = test::loop_beta(n);
      expected = (1 - n * beta) * in.position(v) + beta * test::neighbour_sum(in, v);
    }
    CHECK(close(out.position(w), expected, 1e-12));
  }
  for (FaceId f : out.faces()) {
    const Origin src = o.of(f);
    std::vector<Origin> expected;
    if (src.kind == Kind::corner) {
      const CornerId c = src.corner();
      expected = {origin_of(in.vertex(c)), origin_of(in.edge(c)), origin_of(in.edge(in.prev(c)))};
    } else {
      for (CornerId c : in.corners(src.face())) expected.push_back(origin_of(in.edge(c)));
    }
    CHECK(face_vertex_origins(out, o, f) == expected);
  }
  check_halves_and_corner_edges(in, out, o, [&](CornerId c) {  // cuts off c
    return std::vector<Origin>{origin_of(in.edge(c)), origin_of(in.edge(in.prev(c)))};
  });
}

void check_sqrt3(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return sqrt3(m, origins); }, o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {V, 0, F, 0}, {0, E, 0, C}, {0, 0, 0, C});
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    glm::dvec3 expected;
    if (src.kind == Kind::face) {
      expected = centroid_of(in, src.face());
    } else {
      const VertexId v = src.vertex();
      const double n = in.valence(v), a = test::kobbelt_a(n);
      expected = (1 - a) * in.position(v) + a / n * test::neighbour_sum(in, v);
    }
    CHECK(close(out.position(w), expected, 1e-12));
  }
  for (FaceId f : out.faces()) {
    const CornerId c = o.of(f).corner();
    CHECK(face_vertex_origins(out, o, f) == std::vector<Origin>{origin_of(in.vertex(c)),
                                                                origin_of(in.face(in.opposite(c))),
                                                                origin_of(in.face(c))});
  }
  for (EdgeId e : out.edges()) {
    const Origin src = o.of(e);
    const auto ends = edge_end_origins(out, o, e);
    if (src.kind == Kind::edge) {  // flipped: between the face points on its two sides
      CHECK(same_set(ends, {origin_of(in.face(src.edge(), 0)), origin_of(in.face(src.edge(), 1))}));
    } else {
      const CornerId c = src.corner();
      CHECK(same_set(ends, {origin_of(in.vertex(c)), origin_of(in.face(c))}));
    }
  }
}

// ---- the curve boundary rule on open meshes: hole faces stay whole and stem from themselves; the rest as on
// closed meshes, without the points and polygons of hole faces.

struct OpenSizes {
  std::size_t V, E, F, C, H, B;  // F and C of surface faces; H hole faces with B corners in all
};
OpenSizes open_sizes(const Mesh& m) {
  OpenSizes s{m.num_vertices(), m.num_edges(), m.num_surface_faces(), 0, m.num_hole_faces(), 0};
  for (FaceId f : m.faces()) (m.is_hole(f) ? s.B : s.C) += m.size(f);
  return s;
}

// A hole face of a binary split stems from the input's hole, its vertices alternately from that hole's
// vertices and edges, in its order.
void check_binary_hole(const Mesh& in, const Mesh& out, const Origins& o, FaceId f) {
  const FaceId h = o.of(f).face();
  REQUIRE(h.valid());
  CHECK(in.is_hole(h));
  std::vector<Origin> expected;
  for (CornerId c : in.corners(h)) {
    expected.push_back(origin_of(in.vertex(c)));
    expected.push_back(origin_of(in.edge(c)));
  }
  CHECK(same_cycle(face_vertex_origins(out, o, f), expected));
}

void check_open_catmull_clark(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return catmull_clark(m, origins); }, o);
  const auto [V, E, F, C, H, B] = open_sizes(in);
  check_counts(o, {V, E, F, 0}, {0, 2 * E, 0, C}, {0, 0, H, C});
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    if (src.kind == Kind::face) CHECK(close(out.position(w), centroid_of(in, src.face()), 1e-12));
    if (src.kind == Kind::edge && is_boundary(in, src.edge())) {
      CHECK(close(out.position(w), (in.position(in.from(src.edge())) + in.position(in.to(src.edge()))) / 2.0,
                  1e-12));
    }
  }
  for (FaceId f : out.faces()) {
    if (out.is_hole(f)) {
      check_binary_hole(in, out, o, f);
      continue;
    }
    const CornerId c = o.of(f).corner();
    CHECK(face_vertex_origins(out, o, f) == std::vector<Origin>{origin_of(in.vertex(c)),
                                                                origin_of(in.edge(c)), origin_of(in.face(c)),
                                                                origin_of(in.edge(in.prev(c)))});
  }
  check_halves_and_corner_edges(in, out, o, [&](CornerId c) {
    return std::vector<Origin>{origin_of(in.edge(c)), origin_of(in.face(c))};
  });
}

void check_open_loop(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return loop(m, origins); }, o);
  const auto [V, E, F, C, H, B] = open_sizes(in);
  check_counts(o, {V, E, 0, 0}, {0, 2 * E, 0, C}, {0, 0, F + H, C});
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    if (src.kind == Kind::edge && is_boundary(in, src.edge())) {
      CHECK(close(out.position(w), (in.position(in.from(src.edge())) + in.position(in.to(src.edge()))) / 2.0,
                  1e-12));
    }
  }
  for (FaceId f : out.faces()) {
    const Origin src = o.of(f);
    if (out.is_hole(f)) {
      check_binary_hole(in, out, o, f);
    } else if (src.kind == Kind::corner) {
      const CornerId c = src.corner();
      CHECK(face_vertex_origins(out, o, f) == std::vector<Origin>{origin_of(in.vertex(c)),
                                                                  origin_of(in.edge(c)),
                                                                  origin_of(in.edge(in.prev(c)))});
    } else {
      std::vector<Origin> expected;
      for (CornerId c : in.corners(src.face())) expected.push_back(origin_of(in.edge(c)));
      CHECK(face_vertex_origins(out, o, f) == expected);
    }
  }
  check_halves_and_corner_edges(in, out, o, [&](CornerId c) {
    return std::vector<Origin>{origin_of(in.edge(c)), origin_of(in.edge(in.prev(c)))};
  });
}

// A sqrt(3) step on an open mesh whose loops are all kept (`trisected` false) or all trisected.
void check_open_sqrt3(const Mesh& in, bool trisected) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return sqrt3(m, origins); }, o);
  const auto [V, E, F, C, H, B] = open_sizes(in);
  const std::size_t T = trisected ? B : 0;  // triangles with a trisected edge: no face point, two edge points
  check_counts(o, {V, 2 * T, F - T, 0}, {0, E + 2 * T, 0, C - T}, {0, 0, H, C});
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    if (src.kind == Kind::face) CHECK(close(out.position(w), centroid_of(in, src.face()), 1e-12));
    if (src.kind == Kind::edge) CHECK(is_boundary(in, src.edge()));
  }
  for (FaceId f : out.faces()) {
    const Origin src = o.of(f);
    if (out.is_hole(f)) {
      CHECK(in.is_hole(src.face()));
      CHECK(out.size(f) == (trisected ? 3 : 1) * in.size(src.face()));
      continue;
    }
    // Triangle c holds vertex(c) unless c's edge is trisected; then its two points and vertex(prev c).
    const CornerId c = src.corner();
    const auto around = face_vertex_origins(out, o, f);
    const bool cut = trisected && in.is_hole(in.face(in.opposite(c)));
    CHECK(std::count(around.begin(), around.end(), origin_of(cut ? in.vertex(in.prev(c)) : in.vertex(c))) ==
          1);
    if (cut) CHECK(std::count(around.begin(), around.end(), origin_of(in.edge(c))) == 2);
  }
  // Every edge from an edge lies along it (a flipped edge between the points of its two sides, a kept one or
  // a third of a trisected one); every other one joins the vertex of its corner to a point of its face.
  for (EdgeId e : out.edges()) {
    const Origin src = o.of(e);
    const auto ends = edge_end_origins(out, o, e);
    if (src.kind == Kind::edge) {
      const EdgeId old = src.edge();
      if (!is_boundary(in, old)) {  // each end the point of a side: its face point or on its trisected edge
        for (int side = 0; side < 2; ++side) {
          bool found = false;
          for (const Origin& end : ends) {
            found = found || end == origin_of(in.face(old, side));
            for (CornerId k : in.corners(in.face(old, side))) found = found || end == origin_of(in.edge(k));
          }
          CHECK(found);
        }
      } else if (!trisected) {
        CHECK(same_set(ends, {origin_of(in.from(old)), origin_of(in.to(old))}));
      } else {
        CHECK(std::count(ends.begin(), ends.end(), origin_of(old)) >= 1);
      }
    } else {
      const CornerId c = src.corner();
      CHECK(std::count(ends.begin(), ends.end(), origin_of(in.vertex(c))) == 1);
      const Origin other = ends[0] == origin_of(in.vertex(c)) ? ends[1] : ends[0];
      const bool of_face = other == origin_of(in.face(c));
      bool of_edge = false;
      for (CornerId k : in.corners(in.face(c))) of_edge = of_edge || other == origin_of(in.edge(k));
      CHECK((of_face || of_edge));
    }
  }
}

void check_dual(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(
      in, [](const Mesh& m, Origins* origins) { return dual(m, origins); }, o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {0, 0, F, 0}, {0, E, 0, 0}, {V, 0, 0, 0});
  for (VertexId w : out.vertices()) CHECK(close(out.position(w), centroid_of(in, o.of(w).face()), 1e-12));
  for (FaceId f : out.faces()) {
    std::vector<Origin> around;
    for (CornerId c : in.corners(o.of(f).vertex())) around.push_back(origin_of(in.face(c)));
    CHECK(same_cycle(face_vertex_origins(out, o, f), std::vector<Origin>(around.rbegin(), around.rend())));
  }
  for (EdgeId e : out.edges()) {
    const EdgeId old = o.of(e).edge();
    CHECK(same_set(edge_end_origins(out, o, e), {origin_of(in.face(old, 0)), origin_of(in.face(old, 1))}));
  }
}

void check_dual_honeycomb_dual(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(in, dual_honeycomb_dual, HoneycombParams{.a = 0.6}, o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {V, 0, F, 0}, {0, E, 0, C}, {0, 0, 0, C});
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    if (src.kind == Kind::vertex) {
      // The average of the centroids of its faces, whatever the parameters; it keeps its valence.
      const VertexId v = src.vertex();
      glm::dvec3 sum(0.0);
      for (CornerId c : in.corners(v)) sum += centroid_of(in, in.face(c));
      CHECK(close(out.position(w), sum / double(in.valence(v)), 1e-12));
      CHECK(out.valence(w) == in.valence(v));
    } else {
      CHECK(out.valence(w) == 2 * in.size(src.face()));
    }
  }
  for (FaceId f : out.faces()) {
    const CornerId c = o.of(f).corner();
    const auto corners = face_vertex_origins(out, o, f);
    REQUIRE(corners.size() == 3);
    CHECK(std::count(corners.begin(), corners.end(), origin_of(in.vertex(c))) == 1);
    CHECK(std::count(corners.begin(), corners.end(), origin_of(in.face(c))) == 1);
  }
  for (EdgeId e : out.edges()) {
    const Origin src = o.of(e);
    const auto ends = edge_end_origins(out, o, e);
    if (src.kind == Kind::edge) {
      CHECK(same_set(ends, {origin_of(in.face(src.edge(), 0)), origin_of(in.face(src.edge(), 1))}));
    } else {
      CHECK(same_set(ends, {origin_of(in.vertex(src.corner())), origin_of(in.face(src.corner()))}));
    }
  }
}

void check_mp_honeycomb(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(in, mp_honeycomb, step_params<MpHoneycombParams>(0.4), o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {V, 0, 0, C}, {0, 0, 0, 2 * C}, {0, E, F, 0});
  for (VertexId w : out.vertices()) {
    if (o.of(w).kind == Kind::vertex) CHECK(out.position(w) == in.position(o.of(w).vertex()));
  }
  for (FaceId f : out.faces()) {
    const Origin src = o.of(f);
    const auto corners = face_vertex_origins(out, o, f);
    if (src.kind == Kind::face) {  // the f-face: parallel to its face, above it, the points of its corners
      const FaceId old = src.face();
      std::vector<Origin> expected;
      for (CornerId c : in.corners(old)) expected.push_back(origin_of(c));
      CHECK(corners == expected);
      const glm::dvec3 n = face_normal(in, old);
      CHECK(glm::dot(face_normal(out, f), n) > 1 - 1e-12);
      const double height = glm::dot(
          n, out.position(out.vertex(out.first_corner(f))) - in.position(in.vertex(in.first_corner(old))));
      CHECK(height > 0);
      for (CornerId c : out.corners(f)) {
        CHECK(
            std::abs(glm::dot(n, out.position(out.vertex(c)) - in.position(in.vertex(in.first_corner(old)))) -
                     height) < 1e-12);
      }
    } else {  // the hexagon of an edge: its two ends and the points of the four corners there
      const EdgeId old = src.edge();
      const CornerId c0 = in.corner(old, 0), c1 = in.corner(old, 1);
      CHECK(same_set(corners, {origin_of(in.from(old)), origin_of(in.to(old)), origin_of(c0),
                               origin_of(in.next(c0)), origin_of(c1), origin_of(in.next(c1))}));
    }
  }
  for (EdgeId e : out.edges()) {
    const CornerId x = o.of(e).corner();
    const auto ends = edge_end_origins(out, o, e);
    CHECK((same_set(ends, {origin_of(in.vertex(x)), origin_of(x)}) ||
           same_set(ends, {origin_of(x), origin_of(in.next(x))})));
  }
}

void check_mp_pushing(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(in, mp_pushing, step_params<MpPushingParams>(0.4), o);
  const auto [V, E, F, C] = sizes(in);
  check_counts(o, {V, E, 0, 0}, {0, 2 * E, 0, C}, {0, 0, F, C});
  const glm::dvec3 centre = vertex_centroid(in);
  for (VertexId w : out.vertices()) {
    const Origin src = o.of(w);
    if (src.kind == Kind::edge) {  // ratio 1: the midpoint
      CHECK(close(out.position(w), 0.5 * (in.position(in.from(src.edge())) + in.position(in.to(src.edge()))),
                  1e-12));
    } else {  // pushed from the old position towards the centre, short of it
      const glm::dvec3 old = in.position(src.vertex());
      const glm::dvec3 moved = out.position(w) - old, towards = centre - old;
      CHECK(glm::length(glm::cross(moved, towards)) < 1e-12);
      CHECK(glm::dot(moved, towards) > 0);
      CHECK(glm::length(moved) < glm::length(towards));
    }
  }
  for (FaceId f : out.faces()) {
    const Origin src = o.of(f);
    std::vector<Origin> expected;
    if (src.kind == Kind::face) {  // the central face: on its face's plane, the points of its edges
      const FaceId old = src.face();
      for (CornerId c : in.corners(old)) expected.push_back(origin_of(in.edge(c)));
      const glm::dvec3 n = face_normal(in, old), base = in.position(in.vertex(in.first_corner(old)));
      for (CornerId c : out.corners(f))
        CHECK(std::abs(glm::dot(n, out.position(out.vertex(c)) - base)) < 1e-12);
    } else {
      const CornerId c = src.corner();
      expected = {origin_of(in.vertex(c)), origin_of(in.edge(c)), origin_of(in.edge(in.prev(c)))};
    }
    CHECK(face_vertex_origins(out, o, f) == expected);
  }
  // The cut across corner c joins the points of the edges after and before it.
  check_halves_and_corner_edges(in, out, o, [&](CornerId c) {
    return std::vector<Origin>{origin_of(in.edge(c)), origin_of(in.edge(in.prev(c)))};
  });
}

void check_mlca(const Mesh& in) {
  Origins o;
  const Mesh out = checked_step(in, mlca, o);
  const auto [V, E, F, C] = sizes(in);
  bool quads = true;
  for (FaceId f : in.faces()) quads = quads && (in.size(f) == 4 || in.is_hole(f));
  if (quads) {  // the Catmull-Clark rule
    check_counts(o, {V, E, F, 0}, {0, 2 * E, 0, C}, {0, 0, 0, C});
    for (FaceId f : out.faces()) {
      const CornerId c = o.of(f).corner();
      CHECK(face_vertex_origins(out, o, f) ==
            std::vector<Origin>{origin_of(in.vertex(c)), origin_of(in.edge(c)), origin_of(in.face(c)),
                                origin_of(in.edge(in.prev(c)))});
    }
    for (VertexId w : out.vertices()) {  // a face point stays at its face's centroid
      if (o.of(w).kind == Kind::face) CHECK(close(out.position(w), centroid_of(in, o.of(w).face()), 1e-12));
    }
  } else {  // the rule on the split, taken back through the split
    check_counts(o, {V, 3 * E, F, 2 * C}, {0, 4 * E, 0, 6 * C}, {0, 0, 0, 4 * C});
    // Every vertex of a quad from corner c stems from c, its vertex, its face or its two edges, or from
    // prev(c) (the split's inner edge into the edge point of edge(prev c) is prev(c)'s).
    for (FaceId f : out.faces()) {
      const CornerId c = o.of(f).corner();
      const std::set<std::pair<int, std::uint32_t>> allowed = {
          key(origin_of(c)),          key(origin_of(in.prev(c))), key(origin_of(in.vertex(c))),
          key(origin_of(in.face(c))), key(origin_of(in.edge(c))), key(origin_of(in.edge(in.prev(c))))};
      for (const Origin& x : face_vertex_origins(out, o, f)) CHECK(allowed.count(key(x)) == 1);
    }
  }
  // The vertex of an input vertex: its neighbours stem from the edges at that vertex.
  for (VertexId w : out.vertices()) {
    if (o.of(w).kind != Kind::vertex || out.is_point_sphere(w)) continue;
    const VertexId v = o.of(w).vertex();
    for (CornerId c : out.corners(w)) {
      const Origin n = o.of(out.vertex(out.next(c)));
      REQUIRE(n.kind == Kind::edge);
      CHECK((in.from(n.edge()) == v || in.to(n.edge()) == v));
    }
  }
}

const std::vector<PolygonSoup>& polygon_soups() {
  static const std::vector<PolygonSoup> soups = {test::cube_soup(), test::dodecahedron_soup(),
                                                 test::torus_soup(4, 3),
                                                 to_polygons(test::mixed_polyhedron())};
  return soups;
}

}  // namespace

// ---- the tests
// ----------------------------------------------------------------------------------------------

TEST_CASE("origins: catmull-clark") {
  for (const PolygonSoup& s : polygon_soups()) check_catmull_clark(build_mesh(s));
  check_catmull_clark(build_mesh(test::grid_soup(3, 2)));  // a hole face: its quads are holes
  check_catmull_clark(with_tombstones(test::cube_soup()));
  check_tombstones_renamed(test::cube_soup(), [](const Mesh& m, Origins* o) { return catmull_clark(m, o); });
}

TEST_CASE("origins: doo-sabin") {
  for (const PolygonSoup& s : polygon_soups()) check_doo_sabin(build_mesh(s));
  check_doo_sabin(build_mesh(test::grid_soup(3, 2)));
  check_doo_sabin(with_tombstones(test::dodecahedron_soup()));
  check_tombstones_renamed(test::cube_soup(), [](const Mesh& m, Origins* o) { return doo_sabin(m, o); });
}

TEST_CASE("origins: honeycomb and honeycomb-zw") {
  for (const PolygonSoup& s : polygon_soups()) check_honeycomb(build_mesh(s));
  check_honeycomb(build_mesh(test::grid_soup(3, 2)));
  Mesh with_point = test::cube();
  with_point.create_vertex({5, 5, 5});  // copied through as a point sphere, from its vertex
  check_honeycomb(with_point);
  check_honeycomb(with_tombstones(test::cube_soup()));
  check_tombstones_renamed(test::cube_soup(), [](const Mesh& m, Origins* o) { return honeycomb(m, {}, o); });
  check_tombstones_renamed(test::dodecahedron_soup(),
                           [](const Mesh& m, Origins* o) { return zhang_wang_honeycomb(m, {}, o); });
  // The result's own tombstones have no origin, and a second step reads them fine.
  Origins first, second;
  const Mesh once = honeycomb(test::cube(), {}, &first);
  REQUIRE(once.face_capacity() > once.num_faces());
  const Mesh twice = honeycomb(once, {}, &second);
  check_honeycomb_origins(once, twice, second);
}

TEST_CASE("origins: loop and sqrt3") {
  for (const PolygonSoup& s : test::closed_triangle_soups()) {
    check_loop(build_mesh(s));
    check_sqrt3(build_mesh(s));
  }
  check_loop(with_tombstones(test::icosahedron_soup()));
  check_sqrt3(with_tombstones(test::icosahedron_soup()));
  check_tombstones_renamed(test::octahedron_soup(), [](const Mesh& m, Origins* o) { return loop(m, o); });
  check_tombstones_renamed(test::octahedron_soup(), [](const Mesh& m, Origins* o) { return sqrt3(m, o); });
}

TEST_CASE("origins: catmull-clark, loop and sqrt3 under the curve rule on open meshes") {
  for (const PolygonSoup& soup :
       {test::grid_soup(3, 2), test::open_tube_soup(5, 2), test::grid_with_holes(4, 4, {{1, 1}})}) {
    check_open_catmull_clark(build_mesh(soup));
    const Mesh triangles = build_mesh(test::triangulated(soup));
    check_open_loop(triangles);
    check_open_sqrt3(triangles, false);
    check_open_sqrt3(sqrt3(triangles), true);
  }
  check_open_catmull_clark(with_tombstones(test::grid_soup(3, 2)));
  check_open_loop(with_tombstones(test::triangulated(test::grid_soup(3, 2))));
  check_open_sqrt3(with_tombstones(test::triangulated(test::grid_soup(3, 2))), false);
  check_tombstones_renamed(test::grid_soup(3, 2),
                           [](const Mesh& m, Origins* o) { return catmull_clark(m, o); });
  check_tombstones_renamed(test::triangulated(test::grid_soup(3, 2)),
                           [](const Mesh& m, Origins* o) { return loop(m, o); });
  check_tombstones_renamed(test::triangulated(test::grid_soup(3, 2)),
                           [](const Mesh& m, Origins* o) { return sqrt3(m, o); });
}

TEST_CASE("origins: dual and dual-honeycomb-dual") {
  for (const PolygonSoup& s : polygon_soups()) {
    check_dual(build_mesh(s));
    check_dual_honeycomb_dual(build_mesh(s));
  }
  check_dual(with_tombstones(test::cube_soup()));
  check_dual_honeycomb_dual(with_tombstones(test::dodecahedron_soup()));
  check_tombstones_renamed(test::cube_soup(), [](const Mesh& m, Origins* o) { return dual(m, o); });
  check_tombstones_renamed(test::cube_soup(),
                           [](const Mesh& m, Origins* o) { return dual_honeycomb_dual(m, {}, o); });
}

TEST_CASE("origins: mp-honeycomb, mp-pushing and mhp") {
  for (const PolygonSoup& s : {test::cube_soup(), test::tetrahedron_soup(), test::dodecahedron_soup()}) {
    check_mp_honeycomb(build_mesh(s));
    check_mp_pushing(build_mesh(s));
  }
  check_mp_honeycomb(with_tombstones(test::cube_soup()));
  check_mp_pushing(with_tombstones(test::cube_soup()));
  check_tombstones_renamed(test::cube_soup(),
                           [](const Mesh& m, Origins* o) { return mp_honeycomb(m, {}, o); });
  check_tombstones_renamed(test::cube_soup(), [](const Mesh& m, Origins* o) { return mp_pushing(m, {}, o); });
  MhpParams hp;
  hp.pattern = "HPH";
  check_tombstones_renamed(test::cube_soup(), [&](const Mesh& m, Origins* o) { return mhp(m, hp, {}, o); });
}

TEST_CASE("origins: mhp takes every step's origins back to the input") {
  const Mesh cube = test::cube();
  const std::size_t V = 8, E = 12, F = 6;
  // One step: the step's own origins.
  for (const char* pattern : {"H", "P"}) {
    CAPTURE(pattern);
    MhpParams one;
    one.pattern = pattern;
    Origins a, b;
    mhp(cube, one, {}, &a);
    if (pattern[0] == 'H') {
      mp_honeycomb(cube, {}, &b);
    } else {
      mp_pushing(cube, {}, &b);
    }
    CHECK(a.vertices == b.vertices);
    CHECK(a.edges == b.edges);
    CHECK(a.faces == b.faces);
  }
  // HP and PH, counted step by step from the rules of H and P (see the headers): with C = 2E,
  // HP: vertices V + 6E corners; faces F, E edges, 8E corners; edges 16E corners.
  // PH: vertices V, E edges, 8E corners; faces F, 2E edges, 4E corners; edges 16E corners.
  MhpParams hp, ph;
  hp.pattern = "HP";
  ph.pattern = "PH";
  Origins o_hp, o_ph;
  const Mesh m_hp = mhp(cube, hp, {}, &o_hp);
  const Mesh m_ph = mhp(cube, ph, {}, &o_ph);
  check_well_formed(cube, m_hp, o_hp);
  check_well_formed(cube, m_ph, o_ph);
  check_counts(o_hp, {V, 0, 0, 6 * E}, {0, 0, 0, 16 * E}, {0, E, F, 8 * E});
  check_counts(o_ph, {V, E, 0, 8 * E}, {0, 0, 0, 16 * E}, {0, 2 * E, F, 4 * E});
  // A face from an input face was made, step by step, parallel to it; the vertex of an input vertex was only
  // pushed towards the centre (the origin, the cube's centroid).
  for (const auto* pair : {&o_hp, &o_ph}) {
    const Mesh& out = pair == &o_hp ? m_hp : m_ph;
    for (FaceId f : out.faces()) {
      const Origin src = pair->of(f);
      if (src.kind != Kind::face) continue;
      CHECK(out.size(f) == 4);
      CHECK(glm::dot(face_normal(out, f), face_normal(cube, src.face())) > 1 - 1e-12);
    }
    for (VertexId w : out.vertices()) {
      const Origin src = pair->of(w);
      if (src.kind != Kind::vertex) continue;
      const glm::dvec3 p = cube.position(src.vertex());
      CHECK(glm::length(glm::cross(out.position(w), p)) < 1e-12);
      CHECK(glm::dot(out.position(w), p) > 0);
      CHECK(glm::length(out.position(w)) < glm::length(p));
    }
  }
}

TEST_CASE("origins: mlca on quads, on a mixed mesh (split first) and with a point sphere") {
  check_mlca(test::cube());
  check_mlca(build_mesh(test::torus_soup(4, 3)));
  check_mlca(build_mesh(test::grid_soup(3, 2)));
  check_mlca(test::mixed_polyhedron());
  check_mlca(test::dodecahedron());
  check_mlca(with_tombstones(test::dodecahedron_soup()));
  check_tombstones_renamed(test::cube_soup(), [](const Mesh& m, Origins* o) { return mlca(m, o); });
  check_tombstones_renamed(test::dodecahedron_soup(), [](const Mesh& m, Origins* o) { return mlca(m, o); });
  Mesh with_point = test::cube();
  const VertexId p = with_point.create_vertex({5, 5, 5});
  Origins o;
  const Mesh out = mlca(with_point, &o);
  check_well_formed(with_point, out, o);
  const auto last = VertexId(out.vertex_capacity() - 1);
  CHECK(o.of(last) == origin_of(p));
  CHECK(o.of(out.face(out.corner(last))) == origin_of(p));
  CHECK(out.position(last) == glm::dvec3(5, 5, 5));
}

TEST_CASE("origins: the boundary rules of doo-sabin, the honeycombs, dual and dual-honeycomb-dual") {
  // A grid with a hole (corners of two edges, kept) and a tube with a marked vertex: every element has its
  // origin, and the boundary points stem from what the headers say, where the rules put them.
  Mesh tube = build_mesh(test::open_tube_soup(8, 3));
  tube.add_vertex_attribute<bool>(sharp_vertex_attribute, false)[VertexId(2)] = true;
  for (const Mesh& in : {build_mesh(test::grid_with_holes(4, 3, {{1, 1}})), tube}) {
    for (const std::string name : {"doo-sabin", "honeycomb", "honeycomb-zw", "dual", "dual-honeycomb-dual"}) {
      CAPTURE(name);
      Origins o;
      const Mesh out = apply_scheme(in, name, {}, &o);
      check_well_formed(in, out, o);
      CHECK(apply_scheme(in, name) == out);
      const bool doo_sabin = name == std::string("doo-sabin"), honeycombs = name.rfind("honeycomb", 0) == 0;
      if (!doo_sabin && !honeycombs) continue;
      for (FaceId f : out.faces()) {
        if (!out.is_hole(f)) continue;
        for (CornerId c : out.corners(f)) {
          const glm::dvec3 q = out.position(out.vertex(c));
          const Origin src = o.of(out.vertex(c));
          if (src.kind == Kind::vertex) {  // a honeycomb's vertex point: itself (sharp) or v/2 + (u + w)/4
            REQUIRE(honeycombs);
            const VertexId v = src.vertex();
            CHECK(out.valence(out.vertex(c)) == 2);
            bool found = false;
            for (CornerId h : in.corners(v)) {
              if (!in.is_hole(in.face(h))) continue;
              const glm::dvec3 u = in.position(in.vertex(in.prev(h))), w = in.position(in.vertex(in.next(h)));
              found = found || q == in.position(v) || q == 0.5 * in.position(v) + 0.25 * (u + w);
            }
            CHECK(found);
            continue;
          }
          REQUIRE(src.kind == Kind::corner);
          const CornerId h = src.corner();
          REQUIRE(in.is_hole(in.face(h)));
          const glm::dvec3 a = in.position(in.vertex(h)), b = in.position(in.vertex(in.next(h))),
                           z = in.position(in.vertex(in.prev(h)));
          if (honeycombs) {
            CHECK(q == 0.5 * (a + b));  // the midpoint of the hole corner's edge
          } else {  // Chaikin's points near a on its two boundary edges (or a, or a midpoint, at sharp ends)
            const bool chaikin = close(q, 0.75 * a + 0.25 * b, 1e-15) || close(q, 0.75 * a + 0.25 * z, 1e-15);
            CHECK((chaikin || q == a || q == 0.5 * (a + b) || q == 0.5 * (a + z)));
          }
        }
      }
    }
  }
}

TEST_CASE("origins: through the registry, for every scheme") {
  const Mesh tetrahedron = test::tetrahedron();  // every scheme takes it
  for (const std::string& name : scheme_names()) {
    CAPTURE(name);
    Origins o;
    const Mesh out = apply_scheme(tetrahedron, name, {}, &o);
    check_well_formed(tetrahedron, out, o);
    CHECK(apply_scheme(tetrahedron, name) == out);
  }
  Origins direct, registered;
  catmull_clark(test::cube(), &direct);
  apply_scheme(test::cube(), "catmull-clark", {}, &registered);
  CHECK(direct.faces == registered.faces);
}

TEST_CASE(
    "origins: a per-face colour carried through two Catmull-Clark steps stays on its side of the cube") {
  // Colour i for input face i. A quad of a step stems from a corner, whose face has a colour; two steps give
  // each colour 4 x 4 = 16 quads. The cube's symmetry planes (x = y and the like) separate the regions of the
  // six faces, so every quad of colour i has its centroid strictly on the side of face i: its largest
  // coordinate in absolute value is along the face's normal, with the normal's sign.
  const Mesh cube = test::cube();
  std::vector<int> colour(cube.face_capacity());
  for (FaceId f : cube.faces()) colour[f.index()] = int(f.index());
  Origins o1, o2;
  const Mesh m1 = catmull_clark(cube, &o1);
  const Mesh m2 = catmull_clark(m1, &o2);
  std::vector<int> colour1(m1.face_capacity()), colour2(m2.face_capacity());
  for (FaceId f : m1.faces()) colour1[f.index()] = colour[cube.face(o1.of(f).corner()).index()];
  for (FaceId f : m2.faces()) colour2[f.index()] = colour1[m1.face(o2.of(f).corner()).index()];
  std::map<int, int> quads_of;
  for (FaceId f : m2.faces()) {
    const int c = colour2[f.index()];
    ++quads_of[c];
    const glm::dvec3 n = face_normal(cube, FaceId(std::uint32_t(c)));
    const glm::dvec3 centre = centroid_of(m2, f);
    const int axis = std::abs(n.x) > 0.5 ? 0 : std::abs(n.y) > 0.5 ? 1 : 2;
    for (int other = 0; other < 3; ++other) {
      if (other != axis) CHECK(std::abs(centre[axis]) > std::abs(centre[other]) + 1e-9);
    }
    CHECK(centre[axis] * n[axis] > 0);
  }
  CHECK(quads_of == std::map<int, int>{{0, 16}, {1, 16}, {2, 16}, {3, 16}, {4, 16}, {5, 16}});
}

TEST_CASE("origins: honeycomb faces coloured by origin border the faces of their own face's vertices") {
  // Front faces take their face's colour, faces around old vertices the vertex's; across every side of the
  // front face of f lies the face of a vertex of f, and each vertex of f once.
  const Mesh m = test::dodecahedron();
  Origins o;
  const Mesh out = honeycomb(m, {}, &o);
  for (FaceId f : out.faces()) {
    if (o.of(f).kind != Kind::face) continue;
    std::vector<Origin> across, expected;
    for (CornerId c : out.corners(f)) across.push_back(o.of(out.face(out.opposite(c))));
    for (CornerId c : m.corners(o.of(f).face())) expected.push_back(origin_of(m.vertex(c)));
    CHECK(same_set(across, expected));
  }
}

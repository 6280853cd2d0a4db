// Root-3 the DLFL way, dual(honeycomb(dual(M))): counts, valences and topology on any polygon mesh; on a
// triangle mesh, the connectivity of sqrt(3) under the natural correspondence (input vertex v <-> old vertex
// v, input face f <-> face point of f); the positions derived by hand (old vertices at the average of their
// faces' centroids whatever the honeycomb parameters; the regular tetrahedron completely); affine
// invariance and the errors.

#include <doctest/doctest.h>

#include <algorithm>
#include <map>

#include <dlfl/errors.h>
#include <dlfl/schemes/dual_honeycomb_dual.h>
#include <dlfl/schemes/sqrt3.h>
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

// Where dual(honeycomb(dual(M))) puts input vertex v, for any t and tension. The first dual puts a point at
// every face centroid and makes a face D_v of them around v. The honeycomb replaces D_v by a front face
// whose points are, per formula (1), (1 - t) p_m + t p_{m+1} on D_v's edges (their centroid is D_v's), then
// per formula (2) combinations whose coefficients a_{n,m} depend on n - m mod N only (a circulant matrix
// with rows summing to 1, so its columns sum to 1 too: the centroid is kept again). The second dual puts
// the vertex of that front face at its centroid. So v goes to the average of the centroids of its faces
// (one per corner at v).
glm::dvec3 old_vertex_position(const Mesh& m, VertexId v) {
  glm::dvec3 sum(0.0);
  std::size_t n = 0;
  for (CornerId c : m.corners(v)) {
    sum += centroid(m, m.face(c));
    ++n;
  }
  return sum / double(n);
}

// The output vertex at `p` (to 1e-12); the test meshes have no two output vertices that close.
VertexId vertex_at(const Mesh& m, const glm::dvec3& p) {
  VertexId found;
  for (VertexId v : m.vertices()) {
    if (close(m.position(v), p, 1e-12)) {
      CHECK_FALSE(found.valid());
      found = v;
    }
  }
  return found;
}

}  // namespace

TEST_CASE("dual-honeycomb-dual: counts, valences and genus on meshes of several genera and face mixes") {
  // V' = V + F, E' = 3E, F' = 2E triangles; the vertex of input vertex v keeps its valence, the vertex of
  // input face f has 2 size(f) (dlfl/schemes/dual_honeycomb_dual.h derives these).
  // The default tension needs vertices of valence 3 or more (see the errors below); a constant tension and
  // another t work everywhere and give the same counts and old-vertex positions.
  HoneycombParams other;
  other.t = 0.3;
  other.a = 0.6;
  for (const PolygonSoup& soup : closed_polygon_soups()) {
    CAPTURE(soup.num_faces());
    const Mesh in = build_mesh(soup);
    const auto valences = valence_histogram(in);
    std::vector<HoneycombParams> params{other};
    if (valences.begin()->first >= 3) params.push_back(HoneycombParams{});
    for (const HoneycombParams& p : params) {
      const Mesh copy = in;
      const Mesh out = dual_honeycomb_dual(in, p);
      CHECK(in == copy);
      check_valid_same_genus(in, out);
      CHECK(out.num_vertices() == in.num_vertices() + in.num_faces());
      CHECK(out.num_edges() == 3 * in.num_edges());
      CHECK(out.num_faces() == 2 * in.num_edges());
      CHECK(face_size_histogram(out) == std::map<std::uint32_t, std::size_t>{{3, 2 * in.num_edges()}});
      auto expected = valences;
      for (FaceId f : in.faces()) ++expected[2 * in.size(f)];
      CHECK(valence_histogram(out) == expected);
      // And the vertex of every input vertex is where the derivation above puts it, with its valence.
      for (VertexId v : in.vertices()) {
        const VertexId w = vertex_at(out, old_vertex_position(in, v));
        REQUIRE(w.valid());
        CHECK(out.valence(w) == in.valence(v));
      }
      CHECK(signed_volume(out) > 0);
    }
  }
  CHECK(dual_honeycomb_dual(Mesh{}).empty());
}

TEST_CASE("dual-honeycomb-dual: on a triangle mesh it has the connectivity of sqrt(3), not its positions") {
  for (const PolygonSoup& soup : closed_triangle_soups()) {
    CAPTURE(soup.num_faces());
    const Mesh in = build_mesh(soup);
    const Mesh ours = dual_honeycomb_dual(in);
    const Mesh root3 = sqrt3(in);
    REQUIRE(ours.num_vertices() == root3.num_vertices());
    REQUIRE(ours.num_faces() == root3.num_faces());
    const std::uint32_t V = in.num_vertices();
    // The correspondence: sqrt(3)'s vertex v (v < V) is the vertex at old_vertex_position(v); sqrt(3)'s face
    // point V + f is the vertex joined to the vertices of f's three corners (and to no other old vertex).
    std::vector<std::uint32_t> to_ours(root3.num_vertices(), ~0u);
    std::vector<std::uint32_t> old_of(ours.num_vertices(), ~0u);  // our vertex -> input vertex, if old
    for (VertexId v : in.vertices()) {
      const VertexId w = vertex_at(ours, old_vertex_position(in, v));
      REQUIRE(w.valid());
      to_ours[v.index()] = w.index();
      old_of[w.index()] = v.index();
    }
    std::map<std::vector<std::uint32_t>, std::uint32_t> face_by_vertices;
    for (FaceId f : in.faces()) {
      std::vector<std::uint32_t> key;
      for (VertexId v : face_vertices(in, f)) key.push_back(v.index());
      std::sort(key.begin(), key.end());
      REQUIRE(face_by_vertices.emplace(key, f.index()).second);  // no two triangles on the same vertices
    }
    for (VertexId w : ours.vertices()) {
      if (old_of[w.index()] != ~0u) continue;
      std::vector<std::uint32_t> key;
      for (CornerId c : ours.corners(w)) {
        const std::uint32_t x = old_of[ours.vertex(ours.next(c)).index()];
        if (x != ~0u) key.push_back(x);
      }
      std::sort(key.begin(), key.end());
      const auto it = face_by_vertices.find(key);
      REQUIRE(it != face_by_vertices.end());
      CHECK(to_ours[V + it->second] == ~0u);
      to_ours[V + it->second] = w.index();
    }
    // Under it, every triangle of sqrt(3) is a triangle here, with the same orientation.
    std::vector<std::vector<std::uint32_t>> a, b;
    for (FaceId f : root3.faces()) {
      std::vector<std::uint32_t> t;
      for (VertexId v : face_vertices(root3, f)) t.push_back(to_ours[v.index()]);
      a.push_back(canonical_cycle(t));
    }
    for (FaceId f : ours.faces()) {
      std::vector<std::uint32_t> t;
      for (VertexId v : face_vertices(ours, f)) t.push_back(v.index());
      b.push_back(canonical_cycle(t));
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    CHECK(a == b);
    // The positions differ: an old vertex goes to 1/3 v + 2/3 (average of its neighbours), the
    // face-centroid average above (each neighbour is on two of the n triangles around v), where sqrt(3)
    // weighs the neighbours by a_n = (4 - 2 cos(2 pi / n)) / 9 < 2/3.
    // They agree only where v is the average of its neighbours (flat regular regions).
    double largest_difference = 0;
    for (VertexId v : in.vertices()) {
      glm::dvec3 sum(0.0);
      double n = 0;
      for (CornerId c : in.corners(v)) {
        sum += in.position(in.vertex(in.next(c)));
        n += 1;
      }
      const glm::dvec3 p = ours.position(VertexId(to_ours[v.index()]));
      CHECK(close(p, in.position(v) / 3.0 + 2.0 / 3.0 * sum / n, 1e-12));
      largest_difference = std::max(largest_difference, glm::length(p - root3.position(v)));
    }
    CHECK(largest_difference > 0.01);
  }
}

TEST_CASE("dual-honeycomb-dual: the regular tetrahedron by hand") {
  // Tetrahedron centred at the origin (the vertices sum to 0), tension a for the triangles of the dual.
  // First dual: the face opposite w has centroid -w/3; the dual's face around v is the triangle of the -w/3,
  // w != v, with centroid g_v = -(sum of w != v) / 9 = v / 9. That is where v goes (see the first test).
  // Face points: in a dual triangle (u_0, u_1, u_2) with centroid g and t = 1/2, the edge points are
  // p_m = (u_m + u_{m+1}) / 2, and formula (2) for N = 3 has a_{n,n} = a and a_{n,m} = (1 - a) 2 / 4 else,
  // so v'_n = a p_n + (1 - a)/2 (3g - p_n), i.e. v'_n - g = (3a - 1)/2 (p_n - g). The honeycomb's face
  // around the dual's vertex u_0 = -w/3 (w the vertex opposite face f) collects, from each of the three dual
  // triangles at u_0 (those of the three vertices v of f), its two points next to u_0: v'_0 + v'_2 =
  // 2g + (3a - 1)/2 (p_0 + p_2 - 2g) = 2g + (3a - 1)/4 (u_0 - g), as p_0 + p_2 = u_0/2 + 3g/2. Summing over
  // the three v of f, with g = v/9, sum of v = -w and u_0 = -w/3:
  //   -(2/9) w - (3a - 1)/4 w + (3a - 1)/36 w = -w (8 + 8 (3a - 1)) / 36 = -(2a/3) w
  // over six points, so the vertex of f is at -a w / 9.
  const Mesh in = test::tetrahedron();
  for (const HoneycombParams& p : {HoneycombParams{}, HoneycombParams{0.5, 0.3, 0.45, 1.25}}) {
    const double a = p.a ? *p.a : p.a0 + p.a1 / 3.0;
    const Mesh out = dual_honeycomb_dual(in, p);
    for (VertexId v : in.vertices()) {
      CHECK(vertex_at(out, in.position(v) / 9.0).valid());
      CHECK(vertex_at(out, -a * in.position(v) / 9.0).valid());
    }
  }
}

TEST_CASE("dual-honeycomb-dual: affine invariance") {
  // The mixed polyhedron has a vertex of valence 2: a constant tension.
  HoneycombParams constant;
  constant.a = 0.6;
  check_affine_invariance(test::mixed_polyhedron(),
                          [&](const Mesh& m) { return dual_honeycomb_dual(m, constant); });
  check_affine_invariance(build_mesh(triangulated(torus_soup(5, 4))),
                          [](const Mesh& m) { return dual_honeycomb_dual(m); });
}

TEST_CASE("dual-honeycomb-dual: holes (boundary=hole), point spheres and bad tensions are refused, named") {
  HoneycombParams hole;
  hole.boundary.rule = BoundaryRule::hole;
  CHECK(error_message<TopologyError>([&] { dual_honeycomb_dual(build_mesh(grid_soup(2, 2)), hole); }) ==
        "dual-honeycomb-dual: dual: f4 is a hole: boundary=hole refuses open meshes (boundary=curve gives "
        "their dual)");
  Mesh sphere = test::cube();
  sphere.create_vertex({5, 5, 5});
  CHECK(error_message<TopologyError>([&] { dual_honeycomb_dual(sphere); }) ==
        "dual-honeycomb-dual: dual: v8 is a point sphere (no edge)");
  // A vertex of valence 2 is a 2-gon of the dual, where the default tension 0.45 + 1.25/2 exceeds 1.
  Mesh m = test::cube();
  m.subdivide_edge(EdgeId(0), {0.0, -1.0, -1.0});
  const std::string message = error_message<InvalidArgument>([&] { dual_honeycomb_dual(m); });
  CHECK(message.rfind("dual-honeycomb-dual: honeycomb: tension a0 + a1/N = 1.075", 0) == 0);
  CHECK(message.find("N-valent vertices") != std::string::npos);
  HoneycombParams bad_t;
  bad_t.t = 1.5;
  CHECK(error_message<InvalidArgument>([&] {
          dual_honeycomb_dual(test::cube(), bad_t);
        }).find("parameter t = 1.5") != std::string::npos);
  // A constant tension handles it.
  HoneycombParams constant;
  constant.a = 0.5;
  CHECK(validate(dual_honeycomb_dual(m, constant)).valid());
}

TEST_CASE("dual-honeycomb-dual: through the editor, its undo and the log, with the honeycomb's parameters") {
  const Mesh in = build_mesh(torus_soup(4, 3));
  HoneycombParams p;
  p.t = 0.4;
  p.a = 0.7;
  check_editor_and_log(in, "dual-honeycomb-dual", {{"t", 0.4}, {"a", 0.7}, {"boundary", "hole"}},
                       dual_honeycomb_dual(dual_honeycomb_dual(in, p), p), build_mesh(grid_soup(2, 1)));
  // t's range needs no mesh: it is refused when the parameters are resolved, before any work.
  CHECK_THROWS_WITH_AS(resolve_scheme_params("dual-honeycomb-dual", {{"t", 2.0}}),
                       doctest::Contains("dual-honeycomb-dual: parameter t = 2 is outside [0, 1]"),
                       ParameterError);
  // The tension's range depends on the face sizes (of the dual): checked when the step runs. The cube's dual
  // (the octahedron) has triangles only; a0 + a1/3 = 1.2 is too much.
  CHECK_THROWS_WITH_AS(apply_scheme(test::cube(), "dual-honeycomb-dual", {{"a0", 0.2}, {"a1", 3.0}}),
                       doctest::Contains("dual-honeycomb-dual: honeycomb: tension a0 + a1/N = 1.2"),
                       InvalidArgument);
}

// Doo-Sabin: counts, face sizes and valences, topology, the documented output order, positions derived by
// hand on the cube and re-derived from the weights on a face of 70 sides (the closed form), affine
// invariance, the hole policy and the errors. (Agreement with CGAL's implementation is in tests/oracle.)

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <dlfl/errors.h>
#include <dlfl/schemes/doo_sabin.h>
#include "test_helpers.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

// V' = corners, E' = 2 corners, F' = V + E + F; faces: a copy of every face, a quad per edge, a face of
// valence(v) sides per vertex; every new vertex 4-valent (two F/E/V-face edges meet at each point twice).
void check_counts(const Mesh& in) {
  const Mesh copy = in;
  const Mesh out = doo_sabin(in);
  CHECK(in == copy);
  check_valid_same_genus(in, out);
  CHECK(out.num_vertices() == in.num_corners());
  CHECK(out.num_edges() == 2 * in.num_corners());
  CHECK(out.num_faces() == in.num_vertices() + in.num_edges() + in.num_faces());
  std::map<std::uint32_t, std::size_t> sizes;
  for (FaceId f : in.faces()) ++sizes[in.size(f)];
  sizes[4] += in.num_edges();
  for (VertexId v : in.vertices()) ++sizes[in.valence(v)];
  CHECK(face_size_histogram(out) == sizes);
  CHECK(valence_histogram(out) == std::map<std::uint32_t, std::size_t>{{4, in.num_corners()}});
  CHECK(signed_volume(out) > 0);
}

// The point of the i-th corner (from the first) of face f, summed directly from the published weights
// alpha_0 = 1/4 + 5/(4n), alpha_k = (3 + 2 cos(2 pi k / n)) / (4n).
glm::dvec3 corner_point(const Mesh& m, FaceId f, std::size_t i) {
  const auto v = face_vertices(m, f);
  const std::size_t n = v.size();
  glm::dvec3 p(0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const double alpha =
        k == 0 ? 0.25 + 5.0 / (4.0 * n) : (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * k / n)) / (4.0 * n);
    p += alpha * m.position(v[(i + k) % n]);
  }
  return p;
}

}  // namespace

TEST_CASE("doo-sabin: counts, sizes, valences and genus on meshes of several genera and face mixes") {
  for (const PolygonSoup& soup : closed_polygon_soups()) {
    CAPTURE(soup.num_faces());
    check_counts(build_mesh(soup));
  }
  // A vertex of valence 2 gives a 2-gon V-face, which the kernel holds.
  Mesh cube = test::cube();
  cube.subdivide_edge(EdgeId(0),
                      0.5 * (cube.position(cube.from(EdgeId(0))) + cube.position(cube.to(EdgeId(0)))));
  check_counts(cube);
  CHECK(doo_sabin(Mesh{}).empty());
}

TEST_CASE("doo-sabin: the cube by hand, and the documented output order") {
  const Mesh in = test::cube();
  const Mesh out = doo_sabin(in);
  // On a square face with corners v_0 .. v_3 the weights are alpha_0 = 1/4 + 5/16 = 9/16,
  // alpha_1 = alpha_3 = (3 + 2 cos(pi/2)) / 16 = 3/16, alpha_2 = (3 + 2 cos(pi)) / 16 = 1/16. Along a
  // coordinate tangent to the face the corner has value s, one neighbour s, the other -s and the opposite
  // corner -s: 9s/16 + 3s/16 - 3s/16 - s/16 = s/2. Along the face's normal every corner has the same value,
  // kept (the weights sum to 1). So the point of a corner is its vertex with the two tangent coordinates
  // halved, e.g. (-1/2, -1/2, -1) for vertex (-1, -1, -1) in the face z = -1.
  for (FaceId f : in.faces()) {
    // The normal axis: the coordinate all the face's vertices share.
    const auto verts = face_vertices(in, f);
    int axis = -1;
    for (int k = 0; k < 3; ++k) {
      bool same = true;
      for (VertexId v : verts) same = same && in.position(v)[k] == in.position(verts[0])[k];
      if (same) axis = k;
    }
    REQUIRE(axis >= 0);
    for (CornerId c : in.corners(f)) {
      glm::dvec3 expected = 0.5 * in.position(in.vertex(c));
      expected[axis] *= 2.0;
      // Output vertex k is the point of input corner k.
      CHECK(close(out.position(VertexId(c.index())), expected, 1e-15));
    }
  }
  // Faces: F-faces in face order (starting at the point of the first corner), then E-faces in edge order as
  // (c0, next(c1), c1, next(c0)), then V-faces in vertex order, from corner(v) counter-clockwise
  // (prev_around_vertex).
  std::uint32_t k = 0;
  auto out_face = [&](std::uint32_t index) {
    std::vector<std::uint32_t> v;
    for (VertexId x : face_vertices(out, FaceId(index))) v.push_back(x.index());
    return v;
  };
  for (FaceId f : in.faces()) {
    std::vector<std::uint32_t> expected;
    for (CornerId c : in.corners(f)) expected.push_back(c.index());
    CHECK(out_face(k++) == expected);
  }
  for (EdgeId e : in.edges()) {
    const CornerId c0 = in.corner(e, 0), c1 = in.corner(e, 1);
    CHECK(out_face(k++) ==
          std::vector<std::uint32_t>{c0.index(), in.next(c1).index(), c1.index(), in.next(c0).index()});
  }
  for (VertexId v : in.vertices()) {
    std::vector<std::uint32_t> expected;
    CornerId c = in.corner(v);
    do {
      expected.push_back(c.index());
      c = in.prev_around_vertex(c);
    } while (c != in.corner(v));
    CHECK(out_face(k++) == expected);
  }
  CHECK(k == out.num_faces());
  // All of it turns counter-clockwise seen from outside: the enclosed volume is positive.
  CHECK(signed_volume(out) > 0);
}

TEST_CASE("doo-sabin: a face of 70 sides (closed form) agrees with the weights summed directly") {
  // A prism over an irregular 70-gon, so that the closed form for faces of more than 64 sides is used for
  // the two caps and the direct weights for the quads.
  const int n = 70;
  PolygonSoup s;
  for (int z = 0; z < 2; ++z) {
    for (int i = 0; i < n; ++i) {
      const double u = 2 * std::numbers::pi * i / n, r = 1.0 + 0.2 * std::sin(3.0 * i) + 0.05 * z;
      s.positions.push_back(
          {r * std::cos(u), r * std::sin(u), z == 0 ? -1.0 + 0.1 * std::cos(5.0 * i) : 1.0});
    }
  }
  test::add_prism_faces(s, n);
  const Mesh in = build_mesh(s);
  const Mesh out = doo_sabin(in);
  require_valid(out);
  for (FaceId f : in.faces()) {
    std::size_t i = 0;
    for (CornerId c : in.corners(f))
      CHECK(close(out.position(VertexId(c.index())), corner_point(in, f, i++), 1e-13));
  }
}

TEST_CASE("doo-sabin: affine invariance") {
  check_affine_invariance(test::mixed_polyhedron(), [](const Mesh& m) { return doo_sabin(m); });
  check_affine_invariance(build_mesh(torus_soup(6, 4)), [](const Mesh& m) { return doo_sabin(m); });
}

TEST_CASE(
    "doo-sabin: under boundary=hole a hole is subdivided like a face and its copy stays the only hole") {
  const Mesh in = build_mesh(grid_soup(3, 2));  // 6 quads and one hole of 10 corners; V = 12, E = 17
  REQUIRE(count_holes(in) == 1);
  const Mesh out = doo_sabin(in, BoundaryOptions{BoundaryRule::hole});
  check_valid_same_genus(in, out);
  CHECK(out.num_faces() == 12 + 17 + 7);
  CHECK(count_holes(out) == 1);
  FaceId hole_in, hole_out;
  for (FaceId f : in.faces())
    if (in.is_hole(f)) hole_in = f;
  for (FaceId f : out.faces())
    if (out.is_hole(f)) hole_out = f;
  CHECK(out.size(hole_out) == 10);
  CHECK(hole_out == hole_in);  // the F-face of input face f is output face f
  // The boundary is smoothed as if the 10-gon capped it: the points of the hole's corners are its weighted
  // sums like any face's.
  std::size_t i = 0;
  for (CornerId c : in.corners(hole_in)) {
    CHECK(close(out.position(VertexId(c.index())), corner_point(in, hole_in, i++), 1e-14));
  }
}

TEST_CASE("doo-sabin: point spheres and valence-1 vertices are refused, naming the input's vertex") {
  Mesh m = test::cube();
  m.delete_vertex(m.create_vertex({9, 9, 9}));  // a tombstone v8: the point sphere below is v9
  const VertexId sphere = m.create_vertex({5, 5, 5});
  REQUIRE(sphere == VertexId(9));
  const std::string message = error_message<TopologyError>([&] { doo_sabin(m); });
  CHECK(message.find("doo-sabin: v9 is a point sphere") != std::string::npos);

  // Join the point sphere to a cube corner: v9 now has one edge, with the same face on both sides.
  m.insert_edge(m.corner(VertexId(0)), m.corner(sphere));
  require_valid(m);
  REQUIRE(m.valence(sphere) == 1);
  const std::string valence1 = error_message<TopologyError>([&] { doo_sabin(m); });
  CHECK(valence1.find("doo-sabin: v9 has valence 1") != std::string::npos);
  // Removing the tombstones changes nothing but the names.
  m.compact();
  CHECK(error_message<TopologyError>([&] { doo_sabin(m); }).find("v8 has valence 1") != std::string::npos);
}

TEST_CASE("doo-sabin: through the editor, its undo and the log") {
  Mesh sphere = test::cube();
  sphere.create_vertex({5, 5, 5});
  const Mesh in = build_mesh(torus_soup(4, 3));
  check_editor_and_log(in, "doo-sabin", {}, doo_sabin(doo_sabin(in)), sphere);
}

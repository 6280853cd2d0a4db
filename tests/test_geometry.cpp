// Face and vertex geometry (dlfl/geometry.h) on meshes with hand-derived answers: the cube, the regular
// tetrahedron, an open grid (whose hole face must not tilt the vertex normals), a point sphere and a 2-gon.

#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include <dlfl/geometry.h>
#include <dlfl/navigation.h>
#include "test_meshes.h"

using namespace dlfl;

namespace {
bool close(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-14) {
  return glm::length(a - b) <= tolerance;
}
}  // namespace

TEST_CASE("geometry: the cube [-1, 1]^3") {
  const Mesh m = test::cube();
  for (FaceId f : m.faces()) {
    // Each face is a 2 x 2 square on one axis plane: area 4, centroid at the plane's centre, normal outward
    // along that axis (so the centroid, at distance 1 from the origin, is the normal itself).
    const glm::dvec3 c = face_centroid(m, f);
    CHECK(face_area(m, f) == doctest::Approx(4.0));
    CHECK(glm::length(c) == doctest::Approx(1.0));
    CHECK(close(face_normal(m, f), c));
    CHECK(close(newell_vector(m, f), 8.0 * c));
  }
  // At a corner three equal faces meet, with normals along the three axes towards the vertex.
  for (VertexId v : m.vertices()) CHECK(close(vertex_normal(m, v), m.position(v) / std::sqrt(3.0)));
}

TEST_CASE("geometry: the regular tetrahedron") {
  // Vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) sum to zero. The face without vertex p has the other
  // three, whose sum is -p: centroid -p/3, outward normal -p/sqrt(3). Edges are 2 sqrt(2) long, so each
  // face has area sqrt(3)/4 (2 sqrt(2))^2 = 2 sqrt(3). By symmetry a vertex normal points at the vertex.
  const Mesh m = test::tetrahedron();
  for (FaceId f : m.faces()) {
    glm::dvec3 sum(0.0);
    for (VertexId v : vertices(m, f)) sum += m.position(v);
    const glm::dvec3 p = -sum;  // the vertex not on f
    CHECK(close(face_centroid(m, f), -p / 3.0));
    CHECK(close(face_normal(m, f), -p / std::sqrt(3.0)));
    CHECK(face_area(m, f) == doctest::Approx(2.0 * std::sqrt(3.0)));
  }
  for (VertexId v : m.vertices()) CHECK(close(vertex_normal(m, v), m.position(v) / std::sqrt(3.0)));
}

TEST_CASE("geometry: an open grid; the hole face counts for nothing in vertex normals") {
  const Mesh m = build_mesh(test::grid_soup(3, 2));  // unit quads in z = 0, counter-clockwise from above
  for (FaceId f : m.faces()) {
    if (m.is_hole(f)) {
      // The hole runs the other way round the 3 x 2 rectangle: normal down, area 6.
      CHECK(close(face_normal(m, f), {0, 0, -1}));
      CHECK(face_area(m, f) == doctest::Approx(6.0));
      CHECK(close(face_centroid(m, f), {1.5, 1.0, 0.0}));  // 10 rim vertices, symmetric about the centre
    } else {
      CHECK(close(face_normal(m, f), {0, 0, 1}));
      CHECK(face_area(m, f) == doctest::Approx(1.0));
    }
  }
  // Were the hole counted, its normal (area 6, pointing down) would flip every rim vertex's normal.
  for (VertexId v : m.vertices()) CHECK(close(vertex_normal(m, v), {0, 0, 1}));
}

TEST_CASE("geometry: a triangle far from the origin keeps its area") {
  PolygonSoup s;
  const glm::dvec3 o(1e6, -2e6, 3e6);
  s.positions = {o, o + glm::dvec3(3, 0, 0), o + glm::dvec3(0, 4, 0)};
  s.add_face({0, 1, 2});
  const Mesh m = build_mesh(s);
  const FaceId t = *surface_faces(m).begin();
  CHECK(face_area(m, t) == doctest::Approx(6.0).epsilon(1e-9));
  CHECK(close(face_normal(m, t), {0, 0, 1}, 1e-9));
  CHECK(close(face_centroid(m, t), o + glm::dvec3(1, 4.0 / 3.0, 0), 1e-9));
}

TEST_CASE("geometry: point spheres and 2-gons are degenerate") {
  Mesh m;
  const VertexId a = m.create_vertex({1, 2, 3});
  const FaceId own = m.face(m.corner(a));
  CHECK(face_area(m, own) == 0.0);
  CHECK(face_normal(m, own) == glm::dvec3(0.0));
  CHECK(face_centroid(m, own) == glm::dvec3(1, 2, 3));
  CHECK(vertex_normal(m, a) == glm::dvec3(0.0));
  // Two point spheres joined by an edge: one face of two corners, a 2-gon without area.
  const VertexId b = m.create_vertex({3, 2, 1});
  const InsertEdgeResult joined = m.insert_edge(m.corner(a), m.corner(b));
  const FaceId two = m.face(m.corner(a));
  REQUIRE(m.size(two) == 2);
  CHECK(joined.removed_face.valid());
  CHECK(face_area(m, two) == 0.0);
  CHECK(face_normal(m, two) == glm::dvec3(0.0));
  CHECK(face_centroid(m, two) == glm::dvec3(2, 2, 2));
  CHECK(vertex_normal(m, b) == glm::dvec3(0.0));
}

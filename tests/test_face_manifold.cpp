// CREATEFACEMANIFOLD: N points give 2 faces, N edges, N vertices, two N-gons, genus 0.

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/validate.h>

using namespace dlfl;

TEST_CASE("face manifold: counts and orders and corners for N = 2..12") {
  for (std::size_t n = 2; n <= 12; ++n) {
    CAPTURE(n);
    Mesh m;
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < n; ++i)
      points.push_back({std::cos(double(i)), std::sin(double(i)), double(i)});
    std::vector<VertexId> vs(n);
    std::vector<CornerId> front(n), back(n);
    FaceManifold fm = create_face_manifold(m, points, vs, front, back);
    CHECK(m.num_vertices() == n);
    CHECK(m.num_edges() == n);
    CHECK(m.num_faces() == 2);
    CHECK(m.size(fm.front) == n);
    CHECK(m.size(fm.back) == n);
    auto report = validate(m);
    REQUIRE(report.valid());
    REQUIRE(report.components.size() == 1);
    CHECK(report.components[0].genus == 0);
    // Front runs v_0 .. v_{N-1}, back runs v_{N-1} .. v_0, each from its first corner.
    std::size_t i = 0;
    for (CornerId c : m.corners(fm.front)) {
      CHECK(c == front[i]);
      CHECK(m.vertex(c) == vs[i]);
      CHECK(m.position(vs[i]) == points[i]);
      ++i;
    }
    i = n;
    for (CornerId c : m.corners(fm.back)) {
      --i;
      CHECK(c == back[i]);
      CHECK(m.vertex(c) == vs[i]);
    }
    for (std::size_t k = 0; k < n; ++k) {
      CHECK(m.face(front[k]) == fm.front);
      CHECK(m.face(back[k]) == fm.back);
      CHECK(m.valence(vs[k]) == 2);
    }
  }
}

TEST_CASE("face manifold: bad input is rejected before anything changes") {
  Mesh m;
  std::vector<glm::dvec3> one{{0, 0, 0}};
  CHECK_THROWS_AS(create_face_manifold(m, one), InvalidArgument);
  std::vector<glm::dvec3> bad{{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}};
  CHECK_THROWS_AS(create_face_manifold(m, bad), InvalidArgument);
  std::vector<glm::dvec3> ok{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<CornerId> wrong(2);
  CHECK_THROWS_AS(create_face_manifold(m, ok, {}, wrong), InvalidArgument);
  CHECK(m.num_vertices() == 0);
  CHECK(m.vertex_capacity() == 0);
}

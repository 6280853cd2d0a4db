#pragma once
// Triangle meshes for the tests of Loop and sqrt(3), and helpers shared by the tests of the classic schemes
// (Doo-Sabin, Loop, sqrt(3), dual, dual-honeycomb-dual).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <map>
#include <numbers>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh.h>
#include <dlfl/polygon_soup.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/validate.h>
#include "log_helpers.h"
#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "scheme_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

namespace dlfl::test {

/// Every face of the soup cut into a fan of triangles from its first vertex (for convex faces, and for the
/// quads of the test meshes, the result is a valid triangle mesh of the same topology).
inline PolygonSoup triangulated(const PolygonSoup& soup) {
  PolygonSoup t;
  t.positions = soup.positions;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) t.add_face({face[0], face[k], face[k + 1]});
  }
  return t;
}

/// Closed triangle meshes of genus 0 to 3 with valences from 3 to 8, one of two components.
inline std::vector<PolygonSoup> closed_triangle_soups() {
  return {tetrahedron_soup(),
          octahedron_soup(),
          icosahedron_soup(),
          triangulated(cube_soup()),
          triangulated(dodecahedron_soup()),
          triangulated(to_polygons(mixed_polyhedron())),
          triangulated(torus_soup(6, 5)),
          triangulated(genus_soup(2)),
          triangulated(genus_soup(3)),
          disjoint_union(tetrahedron_soup(), triangulated(torus_soup(5, 4)), {10, 0, 0})};
}

/// Closed polygon meshes of genus 0 to 3 with faces of 3 to 7 sides, one of two components.
inline std::vector<PolygonSoup> closed_polygon_soups() {
  return {tetrahedron_soup(),
          cube_soup(),
          dodecahedron_soup(),
          to_polygons(mixed_polyhedron()),
          icosahedron_soup(),
          torus_soup(7, 5),
          genus_soup(2),
          genus_soup(3),
          triangulated(genus_soup(1)),
          disjoint_union(cube_soup(), torus_soup(5, 4), {10, 0, 0})};
}

/// Two triangles on the same three vertices, back to back (a pillow): every vertex 2-valent, and both
/// triangles of an edge have the same third vertex.
inline PolygonSoup pillow_soup() {
  PolygonSoup pillow;
  pillow.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  pillow.add_face({0, 1, 2});
  pillow.add_face({0, 2, 1});
  return pillow;
}

/// The triangulated torus of genus 1 with every vertex moved off its regular place, so that no rule holds
/// by symmetry alone.
inline Mesh irregular_torus() {
  PolygonSoup soup = triangulated(genus_soup(1));
  for (std::size_t i = 0; i < soup.positions.size(); ++i) {
    soup.positions[i] += 0.1 * glm::dvec3(std::sin(7.0 * i), std::cos(3.0 * i), std::sin(5.0 * i + 1));
  }
  return build_mesh(soup);
}

/// The vertex weights of the triangle schemes for valence n, as published: Loop's beta and Kobbelt's a_n.
inline double loop_beta(double n) {
  const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
  return (5.0 / 8.0 - c * c) / n;
}
inline double kobbelt_a(double n) { return (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / n)) / 9.0; }

/// The sum of the neighbours of v across its edges, which the vertex rules of Loop and sqrt(3) weigh.
inline glm::dvec3 neighbour_sum(const Mesh& m, VertexId v) {
  glm::dvec3 sum(0.0);
  for (CornerId c : m.corners(v)) sum += m.position(m.vertex(m.next(c)));
  return sum;
}

inline bool close(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-12) {
  return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

inline glm::dvec3 centroid(const Mesh& m, FaceId f) {
  glm::dvec3 s(0.0);
  for (CornerId c : m.corners(f)) s += m.position(m.vertex(c));
  return s / double(m.size(f));
}

/// The vertices of a face from its first corner.
inline std::vector<VertexId> face_vertices(const Mesh& m, FaceId f) {
  std::vector<VertexId> v;
  for (CornerId c : m.corners(f)) v.push_back(m.vertex(c));
  return v;
}

/// The same cycle started at its smallest element, so that equal cycles compare equal.
inline std::vector<std::uint32_t> canonical_cycle(std::vector<std::uint32_t> cycle) {
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  return cycle;
}

/// Number of faces by size, and number of vertices by valence.
inline std::map<std::uint32_t, std::size_t> face_size_histogram(const Mesh& m) {
  std::map<std::uint32_t, std::size_t> h;
  for (FaceId f : m.faces()) ++h[m.size(f)];
  return h;
}
inline std::map<std::uint32_t, std::size_t> valence_histogram(const Mesh& m) {
  std::map<std::uint32_t, std::size_t> h;
  for (VertexId v : m.vertices()) ++h[m.valence(v)];
  return h;
}

/// The output is valid and every component keeps its genus (the components keep their order, since the
/// schemes number their output from their input).
inline void check_valid_same_genus(const Mesh& in, const Mesh& out) {
  const ValidationReport before = validate(in);
  const ValidationReport after = validate(out);
  REQUIRE(after.valid());
  REQUIRE(after.components.size() == before.components.size());
  for (std::size_t i = 0; i < before.components.size(); ++i) {
    CHECK(after.components[i].genus == before.components[i].genus);
  }
}

/// What one step of a triangle scheme adds: new vertices, and the edges and faces of the result.
struct TriangleStepCounts {
  std::size_t new_vertices, edges, faces;
};

/// One step of a triangle scheme (Loop, sqrt(3)) against its closed forms: the input unchanged, the result
/// valid with the input's genus and the given counts, every face a triangle, the old vertices (numbered
/// first) keeping their valence and the new ones 6-valent; with `solid` (an input enclosing a positive
/// volume), a positive volume again (the orientation kept).
inline void check_triangle_step(const Mesh& in, Mesh (*scheme)(const Mesh&, Origins*),
                                const TriangleStepCounts& counts, bool solid) {
  CAPTURE(in.num_faces());
  const Mesh copy = in;
  const Mesh out = scheme(in, nullptr);
  CHECK(in == copy);
  check_valid_same_genus(in, out);
  const std::size_t V = in.num_vertices();
  CHECK(out.num_vertices() == V + counts.new_vertices);
  CHECK(out.num_edges() == counts.edges);
  CHECK(out.num_faces() == counts.faces);
  CHECK(face_size_histogram(out) == std::map<std::uint32_t, std::size_t>{{3, counts.faces}});
  std::uint32_t k = 0;
  for (VertexId v : in.vertices()) CHECK(out.valence(VertexId(k++)) == in.valence(v));
  for (; k < V + counts.new_vertices; ++k) CHECK(out.valence(VertexId(k)) == 6);
  if (solid) CHECK(signed_volume(out) > 0);
}

/// A fixed, non-degenerate affine map x -> A x + t.
struct AffineMap {
  glm::dmat3 a{1.2, 0.3, -0.1, 0.2, 0.9, 0.4, -0.3, 0.1, 1.1};
  glm::dvec3 t{0.5, -2.0, 3.0};
  glm::dvec3 operator()(const glm::dvec3& p) const { return a * p + t; }
};

/// Checks scheme(A(mesh)) = A(scheme(mesh)) vertex by vertex (handles are a function of connectivity only).
template <class Scheme>
void check_affine_invariance(const Mesh& in, Scheme scheme) {
  const AffineMap map;
  Mesh moved = in;
  for (VertexId v : moved.vertices()) moved.set_position(v, map(moved.position(v)));
  const Mesh x = scheme(moved);
  const Mesh y = scheme(in);
  REQUIRE(x.num_vertices() == y.num_vertices());
  for (VertexId v : x.vertices()) CHECK(close(x.position(v), map(y.position(v)), 1e-12));
}

/// The number of faces flagged as holes.
inline std::size_t count_holes(const Mesh& m) {
  std::size_t n = 0;
  for (FaceId f : m.faces()) n += m.is_hole(f);
  return n;
}

/// The scheme through the editor and the log, as `dlfl subdivide -s NAME` runs it: two steps equal
/// `expected` (the scheme's function applied twice), undo gives the input back exactly, redo the result, the
/// log replays to an equal mesh, and a step the scheme refuses (on `refused`) leaves the editor unchanged.
inline void check_editor_and_log(const Mesh& in, const std::string& scheme, const SchemeParams& params,
                                 const Mesh& expected, const Mesh& refused) {
  Editor ed;
  ed.set_mesh(in);
  ed.subdivide(scheme, params, 2);
  CHECK(ed.mesh() == expected);
  CHECK(ed.undo());  // both steps are one entry
  CHECK(ed.mesh() == in);
  CHECK(ed.redo());
  CHECK(ed.mesh() == expected);
  CHECK(replay_log(log_text(ed)).mesh() == expected);
  Editor bad;
  bad.set_mesh(refused);
  CHECK_THROWS_AS(bad.subdivide(scheme, params), Error);
  CHECK(bad.mesh() == refused);
  CHECK(bad.undo());  // only the set_mesh entry
  CHECK_FALSE(bad.can_undo());
  // No scheme here takes a parameter named "x".
  CHECK_THROWS_WITH_AS(resolve_scheme_params(scheme, {{"x", 1.0}}),
                       doctest::Contains((scheme + ": unknown parameter 'x'").c_str()), InvalidArgument);
}

}  // namespace dlfl::test

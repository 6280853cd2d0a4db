// The classic schemes agree with CGAL's Subdivision_method_3 on closed meshes, and Catmull-Clark, Loop and
// sqrt(3) on open meshes (boundary=curve): positions to 1e-12, faces exactly.

#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/doo_sabin.h>
#include <dlfl/schemes/loop.h>
#include <dlfl/schemes/sqrt3.h>
#include "../open_meshes.h"
#include "../scheme_meshes.h"
#include "../test_meshes.h"
#include "../triangle_meshes.h"
#include "cgal_compare.h"

using namespace dlfl;
using namespace dlfl::oracle;

namespace {

// Every vertex moved by a different small offset, so that no symmetry of the mesh can hide a wrong weight.
PolygonSoup perturbed(PolygonSoup soup) {
  for (std::size_t i = 0; i < soup.positions.size(); ++i) {
    soup.positions[i] += 0.1 * glm::dvec3(std::sin(7.0 * i), std::cos(3.0 * i), std::sin(5.0 * i + 1));
  }
  return soup;
}

std::vector<PolygonSoup> closed_meshes() {
  return {test::tetrahedron_soup(), test::cube_soup(), test::dodecahedron_soup(), test::torus_soup(6, 5),
          test::genus_soup(2)};
}

// A heptagonal prism with its bottom cut into a triangle and a hexagon and one side quad into two
// triangles: faces of 3, 4, 6 and 7 sides, valences 3 to 5. (test::mixed_polyhedron has a vertex of valence
// 2, whose Doo-Sabin face is a 2-gon, which a polygon list cannot hold.)
PolygonSoup cut_prism() {
  PolygonSoup s;
  for (int z = 0; z < 2; ++z) {
    for (int i = 0; i < 7; ++i) {
      const double u = 2 * std::numbers::pi * i / 7;
      s.positions.push_back({std::cos(u), std::sin(u), z == 0 ? -1.0 : 1.0});
    }
  }
  auto b = [](int i) { return std::uint32_t(i % 7); };
  auto t = [](int i) { return std::uint32_t(7 + i % 7); };
  s.add_face({b(0), b(6), b(1)});
  s.add_face({b(6), b(5), b(4), b(3), b(2), b(1)});
  s.add_face({t(0), t(1), t(2), t(3), t(4), t(5), t(6)});
  for (int i = 0; i < 7; ++i) {
    if (i == 3) {
      s.add_face({b(3), b(4), t(4)});
      s.add_face({b(3), t(4), t(3)});
    } else {
      s.add_face({b(i), b(i + 1), t(i + 1), t(i)});
    }
  }
  return s;
}

// Polygon meshes for Doo-Sabin: the above, faces of 3 to 7 sides, and an irregular one.
std::vector<PolygonSoup> closed_polygon_meshes() {
  auto meshes = closed_meshes();
  meshes.push_back(cut_prism());
  meshes.push_back(perturbed(test::genus_soup(1)));
  return meshes;
}

// Triangle meshes for Loop and sqrt(3), of genus 0 to 2, with valences 3 to 8, and an irregular one.
std::vector<PolygonSoup> closed_triangle_meshes() {
  return {test::tetrahedron_soup(),
          test::octahedron_soup(),
          test::icosahedron_soup(),
          test::triangulated(test::dodecahedron_soup()),
          test::triangulated(test::torus_soup(6, 5)),
          test::triangulated(test::genus_soup(2)),
          perturbed(test::triangulated(test::genus_soup(1)))};
}

// Open polygon meshes: one and two boundary loops, three on a perturbed grid. CGAL has no corner rule, so
// the grids' corners (two edges) are compared with sharp_corners = false.
std::vector<PolygonSoup> open_polygon_meshes() {
  return {test::open_tube_soup(8, 3), test::halves_at_z(test::capped_tube_soup(6, 4)).first,
          perturbed(test::open_tube_soup(5, 2)), test::grid_with_holes(5, 4, {{1, 1}, {3, 2}}),
          perturbed(test::grid_with_holes(4, 4, {{1, 1}}))};
}

// The same triangulated (a fan per face, which leaves every boundary edge as it is).
std::vector<PolygonSoup> open_triangle_meshes() {
  std::vector<PolygonSoup> meshes;
  for (const PolygonSoup& soup : open_polygon_meshes()) meshes.push_back(test::triangulated(soup));
  return meshes;
}

const BoundaryOptions cgal_boundary{BoundaryRule::curve, false};

// Two steps of our scheme and two of CGAL's (`cgal`, given the iteration count) on every soup: the same
// polygons (positions to 1e-12), after a check of our face count against its closed form `faces`.
template <class Ours, class Cgal, class Faces>
void check_two_steps_agree(const std::vector<PolygonSoup>& soups, Ours ours_step, Cgal cgal, Faces faces) {
  for (const PolygonSoup& soup : soups) {
    CAPTURE(soup.num_faces());
    SurfaceMesh sm = to_cgal(soup);
    cgal(sm, CGAL::parameters::number_of_iterations(2));
    const Mesh ours = ours_step(ours_step(build_mesh(soup)));
    CHECK(ours.num_surface_faces() == faces(soup));  // hole faces left out, as CGAL has none
    require_same(to_polygons(ours), from_cgal(sm));
  }
}

}  // namespace

TEST_CASE("oracle: catmull-clark agrees with CGAL on closed meshes") {
  // Every corner becomes a quad, so step 1 has C quads and step 2 has 4 C.
  check_two_steps_agree(
      closed_meshes(), [](const Mesh& m) { return catmull_clark(m); },
      [](SurfaceMesh& sm, auto iterations) {
        CGAL::Subdivision_method_3::CatmullClark_subdivision(sm, iterations);
      },
      [](const PolygonSoup& soup) { return 4 * soup.indices.size(); });
}

TEST_CASE("oracle: doo-sabin agrees with CGAL on closed meshes") {
  // CGAL's DooSabin_mask_3 uses alpha_0 = (5/n + 1)/4 and alpha_k = (3 + 2 cos(2 pi k / n)) / (4n), our
  // weights, with the quad case written out as 9/16, 3/16, 1/16, 3/16; its DQQ step makes the same F-, E- and
  // V-faces.
  // Step 1: F1 = V + E + F, with one vertex per corner (V1 = C), each 4-valent (E1 = 2 C); step 2:
  // F2 = V1 + E1 + F1 = 3 C + V + E + F, with E = C / 2 on a closed mesh.
  check_two_steps_agree(
      closed_polygon_meshes(), [](const Mesh& m) { return doo_sabin(m); },
      [](SurfaceMesh& sm, auto iterations) {
        CGAL::Subdivision_method_3::DooSabin_subdivision(sm, iterations);
      },
      [](const PolygonSoup& soup) {
        const std::size_t c = soup.indices.size();
        return 3 * c + soup.positions.size() + c / 2 + soup.num_faces();
      });
}

TEST_CASE("oracle: loop agrees with CGAL on closed triangle meshes") {
  // CGAL's Loop_mask_3 writes the vertex rule as (n (1 - C_n)/C_n S + R) / (n / C_n) with
  // C_n = 5/8 - (3 + 2 cos(2 pi / n))^2 / 64 = n beta, i.e. (1 - n beta) S + beta R (and 10/16, 1/16 for n =
  // 6), and the edge rule as (3 (a + b) + c + d) / 8: the same rules, rounded differently (well below 1e-12
  // here).
  check_two_steps_agree(
      closed_triangle_meshes(), [](const Mesh& m) { return loop(m); },
      [](SurfaceMesh& sm, auto iterations) { CGAL::Subdivision_method_3::Loop_subdivision(sm, iterations); },
      [](const PolygonSoup& soup) { return 16 * soup.num_faces(); });  // 4 F per step
}

TEST_CASE("oracle: sqrt3 agrees with CGAL on closed triangle meshes") {
  // CGAL's Sqrt3_1step: centroid face points (Linear_mask_3::face_node), the vertex rule with
  // a_n = (4 - 2 cos(2 pi / n)) / 9, add_center_vertex per triangle, then every old edge flipped by join_face
  // and split_face: the same rules and the same flip, so the triangles (with their orientation) agree too.
  // Its boundary rule (every second step) is not compared: we refuse open meshes.
  check_two_steps_agree(
      closed_triangle_meshes(), [](const Mesh& m) { return sqrt3(m); },
      [](SurfaceMesh& sm, auto iterations) { CGAL::Subdivision_method_3::Sqrt3_subdivision(sm, iterations); },
      [](const PolygonSoup& soup) { return 9 * soup.num_faces(); });  // 3 F per step
}

TEST_CASE("oracle: catmull-clark agrees with CGAL on open meshes (boundary=curve)") {
  // CGAL's CatmullClark_mask_3::border_node puts a border edge's point at its midpoint and a border vertex at
  // (u + 6 v + w) / 8 of its border neighbours u, w, which PQQ_1step uses for every vertex on the border; the
  // border stays one loop of twice the edges. Our curve rule, corners included (sharp_corners = false).
  // The surface polygons count as in the closed case: 4 per surface corner after two steps.
  check_two_steps_agree(
      open_polygon_meshes(), [](const Mesh& m) { return catmull_clark(m, cgal_boundary); },
      [](SurfaceMesh& sm, auto iterations) {
        CGAL::Subdivision_method_3::CatmullClark_subdivision(sm, iterations);
      },
      [](const PolygonSoup& soup) { return 4 * soup.indices.size(); });
}

TEST_CASE("oracle: loop agrees with CGAL on open triangle meshes (boundary=curve)") {
  // Loop_mask_3::border_node is the same pair of rules (midpoint, (u + 6 v + w) / 8), used by PTQ_1step for
  // every border edge and vertex.
  check_two_steps_agree(
      open_triangle_meshes(), [](const Mesh& m) { return loop(m, cgal_boundary); },
      [](SurfaceMesh& sm, auto iterations) { CGAL::Subdivision_method_3::Loop_subdivision(sm, iterations); },
      [](const PolygonSoup& soup) { return 16 * soup.num_faces(); });
}

TEST_CASE("oracle: sqrt3 agrees with CGAL on open triangle meshes over pairs of steps (boundary=curve)") {
  // Sqrt3_1step refines the border only in every second step of one call (refine_border = i % 2 == 1): in
  // the first, border vertices stay and border edges are not flipped; in the second, Sqrt3_mask_3::
  // border_node puts two points on each border edge s -> t at (r + 16 s + 10 t) / 27 and (10 s + 16 t + u)
  // / 27 (r before s, u after t) and moves the border vertices to (4 r + 19 s + 4 t) / 27, the triangle on
  // the edge is cut into three from its third vertex, and the other old edges are flipped. Ours, with the
  // parity carried from step to step by the sqrt3_trisect mark; compared after 2 and 4 steps (9 and 81 F).
  check_two_steps_agree(
      open_triangle_meshes(), [](const Mesh& m) { return sqrt3(m, cgal_boundary); },
      [](SurfaceMesh& sm, auto iterations) { CGAL::Subdivision_method_3::Sqrt3_subdivision(sm, iterations); },
      [](const PolygonSoup& soup) { return 9 * soup.num_faces(); });
  for (const PolygonSoup& soup : open_triangle_meshes()) {
    CAPTURE(soup.num_faces());
    SurfaceMesh sm = to_cgal(soup);
    CGAL::Subdivision_method_3::Sqrt3_subdivision(sm, CGAL::parameters::number_of_iterations(4));
    Mesh ours = build_mesh(soup);
    for (int step = 0; step < 4; ++step) ours = sqrt3(ours, cgal_boundary);
    CHECK(ours.num_surface_faces() == 81 * soup.num_faces());
    require_same(to_polygons(ours), from_cgal(sm));
  }
}

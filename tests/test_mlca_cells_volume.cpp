// MLCA on hexahedral volumes (d = 3) and the conversions of section 3.3: counts, tri-cubic B-spline rules in
// the interior of a grid, crease vertices, curves and surfaces inside a volume, and the splits of polygons
// into quads and of 3-valent polyhedra into hexahedra.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/cells/cell_average.h>
#include <dlfl/cells/convert.h>
#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/cells/multilinear_subdivide.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/dual.h>
#include "scheme_meshes.h"
#include "test_meshes.h"
#include "test_mlca_cells_util.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

using Fine = std::array<int, 3>;

// Fine lattice coordinates of every vertex after `steps` multi-linear subdivisions of a grid placed on the
// integer lattice: the positions are exact dyadic numbers, so 2^steps times them are the coordinates. The
// numbering does not depend on positions, so these indices hold for any placement of the same grid.
std::map<Fine, std::uint32_t> fine_lattice(CellComplex grid, int nx, int ny, int steps) {
  for (int k = 0; k < int(grid.positions.size()); ++k) {
    const int i = k % (nx + 1), j = k / (nx + 1) % (ny + 1), l = k / ((nx + 1) * (ny + 1));
    grid.positions[k] = glm::dvec3(i, j, l);
  }
  for (int s = 0; s < steps; ++s) grid = multilinear_subdivide(grid);
  std::map<Fine, std::uint32_t> at;
  const double scale = double(1 << steps);
  for (std::uint32_t v = 0; v < grid.positions.size(); ++v) {
    const glm::dvec3 f = grid.positions[v] * scale;
    const Fine key{int(std::lround(f.x)), int(std::lround(f.y)), int(std::lround(f.z))};
    REQUIRE(glm::length(f - glm::dvec3(key[0], key[1], key[2])) == 0.0);
    REQUIRE(at.emplace(key, v).second);
  }
  return at;
}

// The signed volume of the parallelepiped of the three edges of hexahedron corner k, oriented as the axes.
double corner_jacobian(const CellComplex& c, std::size_t cell, int k) {
  const auto h = c.cell(cell);
  glm::dvec3 axis[3];
  for (int i = 0; i < 3; ++i) {
    axis[i] = c.positions[h[k ^ (1 << i)]] - c.positions[h[k]];
    if ((k >> i) & 1) axis[i] = -axis[i];
  }
  return glm::dot(axis[0], glm::cross(axis[1], axis[2]));
}

// Distinct sub-faces of a complex, counted independently of the code: sorted vertex sets of every edge, face
// and cube of every cell.
std::array<std::size_t, 3> distinct_faces(const CellComplex& c) {
  std::array<std::set<std::vector<std::uint32_t>>, 3> seen;
  for (std::size_t i = 0; i < c.num_cells(); ++i) {
    const auto cell = c.cell(i);
    const int n = int(cell.size());
    // A face of the cube: fixed bits `value` on the axes of `mask`, free elsewhere.
    for (int mask = 0; mask < n; ++mask) {
      for (int value = 0; value < n; ++value) {
        if ((value & ~mask) != 0) continue;
        std::vector<std::uint32_t> face;
        for (int k = 0; k < n; ++k) {
          if ((k & mask) == value) face.push_back(cell[k]);
        }
        if (face.size() < 2) continue;
        std::sort(face.begin(), face.end());
        seen[std::countr_zero(face.size()) - 1].insert(face);
      }
    }
  }
  return {seen[0].size(), seen[1].size(), seen[2].size()};
}

}  // namespace

TEST_CASE("mlca cells: one cube gives 8 hexahedra in tensor-product order") {
  const CellComplex cube =
      hex_grid(1, 1, 1, [](int i, int j, int k) { return glm::dvec3(2 * i, 2 * j, 2 * k); });
  const CellComplex split = multilinear_subdivide(cube);
  CHECK(split.positions.size() == 27);
  REQUIRE(split.num_cells() == 8);
  // Sub-cell s spans [s_i, s_i + 1] along axis i; its corner k sits at s + k.
  for (int s = 0; s < 8; ++s) {
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 expected((s & 1) + (k & 1), (s >> 1 & 1) + (k >> 1 & 1), (s >> 2) + (k >> 2));
      CHECK(split.positions[split.cell(s)[k]] == expected);
    }
  }
  // One MLCA step: a corner of the lone cube sees one fine cube, so it moves to that cube's centroid.
  const CellComplex out = mlca_subdivide(cube);
  CHECK(out.positions[0] == glm::dvec3(0.5, 0.5, 0.5));
  CHECK(out.positions[7] == glm::dvec3(1.5, 1.5, 1.5));
  // The centre of the cube is in all 8 and stays.
  CHECK(out.positions[split.cell(0)[7]] == glm::dvec3(1, 1, 1));
}

TEST_CASE("mlca cells: counts after splitting are V + E + F + C vertices and 2^d cells per d-cell") {
  std::vector<CellComplex> complexes;
  complexes.push_back(hex_grid(3, 2, 4, jittered_lattice(1)));
  // The same grid with creases on its boundary: faces, edges, corners. They add cells, never vertices.
  CellComplex creased = hex_grid(2, 2, 2, jittered_lattice(2));
  auto id = [](int i, int j, int k) { return lattice_index(2, 2, i, j, k); };
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      creased.add_cell({id(a, b, 0), id(a + 1, b, 0), id(a, b + 1, 0), id(a + 1, b + 1, 0)});
      creased.add_cell({id(a, 0, b), id(a + 1, 0, b), id(a, 0, b + 1), id(a + 1, 0, b + 1)});
    }
    creased.add_cell({id(a, 0, 0), id(a + 1, 0, 0)});
  }
  creased.add_cell({id(0, 0, 0)});
  complexes.push_back(creased);
  complexes.push_back(polyhedron_to_hexahedra(test::dodecahedron()));
  for (const CellComplex& c : complexes) {
    const auto [edges, faces, cubes] = distinct_faces(c);
    std::size_t cells = 0;
    for (std::size_t i = 0; i < c.num_cells(); ++i) cells += std::size_t(1) << c.dimension(i);
    const CellComplex out = mlca_subdivide(c);
    CHECK(out.positions.size() == c.positions.size() + edges + faces + cubes);
    CHECK(out.num_cells() == cells);
    check_cell_complex(out);
  }
  // Closed forms for the grid: (2n+1) vertices per axis, 8 per hexahedron; the crease cells add none.
  CHECK(mlca_subdivide(complexes[0]).positions.size() == 7 * 5 * 9);
  CHECK(mlca_subdivide(complexes[1]).positions.size() == 5 * 5 * 5);
  CHECK(mlca_subdivide(complexes[1]).num_cells() == 8 * 8 + 8 * 4 + 2 * 2 + 1);
  // A complex of hexahedra that fill a ball keeps V - E + F - C = 1.
  for (const CellComplex& c : {complexes[0], complexes[2]}) {
    const CellComplex out = mlca_subdivide(c, 2);
    const auto [e, f, k] = distinct_faces(out);
    CHECK(std::int64_t(out.positions.size()) - std::int64_t(e) + std::int64_t(f) - std::int64_t(k) == 1);
  }
}

TEST_CASE("mlca cells: a regular grid gets tri-cubic B-spline subdivision in its interior") {
  const int n = 4;
  const CellComplex grid = hex_grid(n, n, n, jittered_lattice(42));
  const auto at = fine_lattice(grid, n, n, 1);
  const CellComplex out = mlca_subdivide(grid);
  int checked = 0;
  for (int I = 1; I < 2 * n; ++I) {
    for (int J = 1; J < 2 * n; ++J) {
      for (int K = 1; K < 2 * n; ++K) {
        glm::dvec3 expected(0.0);
        for (auto [i, wi] : bspline_refinement(I)) {
          for (auto [j, wj] : bspline_refinement(J)) {
            for (auto [k, wk] : bspline_refinement(K))
              expected += wi * wj * wk * grid.positions[lattice_index(n, n, i, j, k)];
          }
        }
        CHECK(glm::length(out.positions[at.at({I, J, K})] - expected) < 1e-13);
        ++checked;
      }
    }
  }
  CHECK(checked == 7 * 7 * 7);
}

TEST_CASE("mlca cells: crease vertices (0-cells) are interpolated in a volume") {
  CellComplex c = hex_grid(2, 2, 2, jittered_lattice(8));
  const std::vector<std::uint32_t> pinned = {lattice_index(2, 2, 0, 0, 0), lattice_index(2, 2, 2, 2, 2),
                                             lattice_index(2, 2, 2, 0, 1), lattice_index(2, 2, 1, 1, 1)};
  for (std::uint32_t v : pinned) c.add_cell({v});
  const CellComplex out = mlca_subdivide(c, 3);
  for (std::uint32_t v : pinned) CHECK(out.positions[v] == c.positions[v]);
  // Without the 0-cells those vertices move.
  const CellComplex free = mlca_subdivide(hex_grid(2, 2, 2, jittered_lattice(8)), 3);
  for (std::uint32_t v : pinned) CHECK(glm::length(free.positions[v] - c.positions[v]) > 1e-3);
}

TEST_CASE("mlca cells: a crease curve inside a volume follows the cubic B-spline curve rules") {
  const int n = 4;
  CellComplex c = hex_grid(n, n, n, jittered_lattice(77));
  // The lattice line j = 2, k = 1 from i = 0 to 4, through the interior and out to the boundary.
  std::vector<glm::dvec3> curve;
  for (int i = 0; i <= n; ++i) curve.push_back(c.positions[lattice_index(n, n, i, 2, 1)]);
  for (int i = 0; i < n; ++i) c.add_cell({lattice_index(n, n, i, 2, 1), lattice_index(n, n, i + 1, 2, 1)});
  // The curve on its own, by the rules re-derived for a curve with free ends: even (1/8, 3/4, 1/8), odd
  // (1/2, 1/2), an end 3/4 of itself and 1/4 of its neighbour.
  auto refine = [](const std::vector<glm::dvec3>& p) {
    std::vector<glm::dvec3> q(2 * p.size() - 1);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i == 0) {
        q[0] = 0.75 * p[0] + 0.25 * p[1];
      } else if (i + 1 == p.size()) {
        q[2 * i] = 0.75 * p[i] + 0.25 * p[i - 1];
      } else {
        q[2 * i] = (p[i - 1] + 6.0 * p[i] + p[i + 1]) / 8.0;
      }
      if (i + 1 < p.size()) q[2 * i + 1] = 0.5 * (p[i] + p[i + 1]);
    }
    return q;
  };
  const int steps = 2;
  const auto at = fine_lattice(c, n, n, steps);
  const CellComplex out = mlca_subdivide(c, steps);
  for (int s = 0; s < steps; ++s) curve = refine(curve);
  const int scale = 1 << steps;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    CAPTURE(i);
    CHECK(glm::length(out.positions[at.at({int(i), 2 * scale, 1 * scale})] - curve[i]) < 1e-13);
  }
}

TEST_CASE("mlca cells: a crease surface inside a volume follows the bi-cubic rules in its interior") {
  const int n = 4;
  CellComplex c = hex_grid(n, n, n, jittered_lattice(13));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      c.add_cell({lattice_index(n, n, i, j, 2), lattice_index(n, n, i + 1, j, 2),
                  lattice_index(n, n, i, j + 1, 2), lattice_index(n, n, i + 1, j + 1, 2)});
    }
  }
  const auto at = fine_lattice(c, n, n, 1);
  const CellComplex out = mlca_subdivide(c);
  for (int I = 1; I < 2 * n; ++I) {
    for (int J = 1; J < 2 * n; ++J) {
      glm::dvec3 expected(0.0);
      for (auto [i, wi] : bspline_refinement(I)) {
        for (auto [j, wj] : bspline_refinement(J))
          expected += wi * wj * c.positions[lattice_index(n, n, i, j, 2)];
      }
      CHECK(glm::length(out.positions[at.at({I, J, 4})] - expected) < 1e-13);
    }
  }
}

TEST_CASE(
    "mlca cells: a cube with crease quads on its faces has the surface of the 6 quads alone (figure 7)") {
  const CellComplex cube = hex_grid(1, 1, 1, jittered_lattice(31));
  CellComplex surface;
  surface.positions = cube.positions;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      std::vector<std::uint32_t> quad;  // the face's corners in the cube's order, still tensor-product order
      for (std::uint32_t k = 0; k < 8; ++k) {
        if (int((k >> axis) & 1) == side) quad.push_back(k);
      }
      surface.add_cell(quad);
    }
  }
  CellComplex volume = cube;
  for (std::size_t i = 0; i < surface.num_cells(); ++i) volume.add_cell(surface.cell(i));
  const int steps = 2;
  const auto in_volume = fine_lattice(volume, 1, 1, steps);
  const auto on_surface = fine_lattice(surface, 1, 1, steps);
  const CellComplex a = mlca_subdivide(volume, steps), b = mlca_subdivide(surface, steps);
  REQUIRE(on_surface.size() == 6 * 4 * 4 + 2);  // the 5^3 lattice minus its 3^3 interior
  for (const auto& [fine, v] : on_surface) {
    CHECK(glm::length(a.positions[in_volume.at(fine)] - b.positions[v]) < 1e-14);
  }
}

TEST_CASE("mlca cells: polygons split into n quads each, sharing edge midpoints") {
  PolygonSoup soup = test::cube_soup();
  soup.add_face({0, 1, 3});  // a non-manifold triangle inside: edge 0-1 now has three faces
  const CellComplex quads = polygons_to_quads(soup);
  // V + E + F: 8 + (12 cube edges + the diagonal 0-3) + 7.
  CHECK(quads.positions.size() == 8 + 13 + 7);
  CHECK(quads.num_cells() == 24 + 3);
  check_cell_complex(quads);
  for (std::size_t f = 0, k = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    glm::dvec3 centroid(0.0);
    for (std::uint32_t v : face) centroid += soup.positions[v] / double(face.size());
    for (std::size_t j = 0; j < face.size(); ++j, ++k) {
      const auto q = quads.cell(k);
      const glm::dvec3 v = soup.positions[face[j]];
      const glm::dvec3 next = soup.positions[face[(j + 1) % face.size()]];
      const glm::dvec3 prev = soup.positions[face[(j + face.size() - 1) % face.size()]];
      CHECK(q[0] == face[j]);
      CHECK(quads.positions[q[1]] == 0.5 * (v + next));
      CHECK(quads.positions[q[2]] == 0.5 * (prev + v));
      CHECK(glm::length(quads.positions[q[3]] - centroid) < 1e-15);
      // Same turning sense as the face: the quad's normal (x-axis cross y-axis) agrees with the face's.
      const glm::dvec3 quad_normal = glm::cross(quads.positions[q[1]] - v, quads.positions[q[2]] - v);
      const glm::dvec3 face_normal = glm::cross(next - v, prev - v);
      CHECK(glm::dot(quad_normal, face_normal) > 0);
    }
  }
  // MLCA runs on the result.
  CHECK(mlca_subdivide(quads, 2).num_cells() == 27 * 16);

  PolygonSoup two_gon = test::cube_soup();
  two_gon.add_face({0, 1});
  CHECK_THROWS_WITH_AS(polygons_to_quads(two_gon), doctest::Contains("face 6 has fewer than 3"),
                       InvalidArgument);
  PolygonSoup repeated = test::cube_soup();
  repeated.add_face({0, 1, 0, 2});
  CHECK_THROWS_WITH_AS(polygons_to_quads(repeated), doctest::Contains("face 6 uses vertex 0 twice"),
                       InvalidArgument);
  PolygonSoup out_of_range = test::cube_soup();
  out_of_range.add_face({0, 1, 9});
  CHECK_THROWS_WITH_AS(polygons_to_quads(out_of_range), doctest::Contains("face 6 uses vertex 9"),
                       InvalidArgument);
}

TEST_CASE("mlca cells: 3-valent polyhedra split into one proper hexahedron per vertex") {
  struct Case {
    const char* name;
    Mesh mesh;
  };
  PolygonSoup prism;
  prism.positions = {{1, 0, 0}, {-0.5, 0.8, 0}, {-0.5, -0.8, 0}, {1, 0, 2}, {-0.5, 0.8, 2}, {-0.5, -0.8, 2}};
  prism.add_face({0, 2, 1});  // counter-clockwise seen from outside
  prism.add_face({3, 4, 5});
  prism.add_face({0, 1, 4, 3});
  prism.add_face({1, 2, 5, 4});
  prism.add_face({2, 0, 3, 5});
  std::vector<Case> cases = {{"tetrahedron", test::tetrahedron()},
                             {"cube", test::cube()},
                             {"prism", build_mesh(prism)},
                             {"dodecahedron", test::dodecahedron()}};
  for (const Case& k : cases) {
    CAPTURE(k.name);
    const Mesh& m = k.mesh;
    const CellComplex hexes = polyhedron_to_hexahedra(m);
    CHECK(hexes.num_cells() == m.num_vertices());
    CHECK(hexes.positions.size() == m.num_vertices() + m.num_edges() + m.num_faces() + 1);
    check_cell_complex(hexes);
    for (std::size_t i = 0; i < hexes.num_cells(); ++i) {
      REQUIRE(hexes.dimension(i) == 3);
      for (int corner = 0; corner < 8; ++corner) CHECK(corner_jacobian(hexes, i, corner) > 0);
    }
    // Each hexahedron has 3 faces on the surface (those at its vertex) and 3 inside, each shared with the
    // hexahedron across one edge: 3V faces used once, E faces used twice.
    std::map<std::vector<std::uint32_t>, int> uses;
    for (std::size_t i = 0; i < hexes.num_cells(); ++i) {
      const auto h = hexes.cell(i);
      for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
          std::vector<std::uint32_t> face;
          for (int c = 0; c < 8; ++c) {
            if (((c >> axis) & 1) == side) face.push_back(h[c]);
          }
          std::sort(face.begin(), face.end());
          ++uses[face];
        }
      }
    }
    std::size_t once = 0, twice = 0;
    for (const auto& [face, count] : uses) {
      once += count == 1;
      twice += count == 2;
    }
    CHECK(once == 3 * m.num_vertices());
    CHECK(twice == m.num_edges());
    CHECK(once + twice == uses.size());
  }
  // Two tetrahedra: two polyhedra, each with its own centroid.
  const PolygonSoup tetrahedron = test::tetrahedron_soup();
  PolygonSoup pair = tetrahedron;
  for (std::size_t v = 0; v < 4; ++v) pair.positions.push_back(pair.positions[v] + glm::dvec3(5, 0, 0));
  for (std::size_t f = 0; f < 4; ++f) {
    const auto t = tetrahedron.face(f);
    pair.add_face({t[0] + 4, t[1] + 4, t[2] + 4});
  }
  const CellComplex two = polyhedron_to_hexahedra(build_mesh(pair));
  CHECK(two.num_cells() == 8);
  REQUIRE(two.positions.size() == 8 + 12 + 8 + 2);
  CHECK(two.positions[28] == glm::dvec3(0, 0, 0));
  CHECK(two.positions[29] == glm::dvec3(5, 0, 0));
  for (std::size_t i = 0; i < 8; ++i) CHECK(two.cell(i)[7] == (i < 4 ? 28u : 29u));
  // The cube splits into the 2 x 2 x 2 grid of half cubes.
  const CellComplex cube = polyhedron_to_hexahedra(test::cube());
  for (std::size_t i = 0; i < cube.num_cells(); ++i) {
    const auto h = cube.cell(i);
    CHECK(glm::length(cube.positions[h[7]]) == 0.0);
    CHECK(glm::length(cube.positions[h[0]]) == doctest::Approx(std::sqrt(3.0)));
  }
}

TEST_CASE("mlca cells: polyhedra that cannot be split into hexahedra are refused, naming the element") {
  PolygonSoup octahedron;
  octahedron.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (auto f : std::vector<std::array<std::uint32_t, 3>>{
           {0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}) {
    octahedron.add_face({f[0], f[1], f[2]});
  }
  CHECK_THROWS_WITH_AS(polyhedron_to_hexahedra(build_mesh(octahedron)), doctest::Contains("v0 has valence 4"),
                       TopologyError);
  // A torus whose vertices are all 3-valent (the dual of a triangulated torus): not a sphere.
  PolygonSoup torus = test::torus_soup(4, 3);
  PolygonSoup triangles;
  triangles.positions = torus.positions;
  for (std::size_t f = 0; f < torus.num_faces(); ++f) {
    const auto q = torus.face(f);
    triangles.add_face({q[0], q[1], q[2]});
    triangles.add_face({q[0], q[2], q[3]});
  }
  CHECK_THROWS_WITH_AS(polyhedron_to_hexahedra(dual(build_mesh(triangles))),
                       doctest::Contains("has Euler characteristic 0"), TopologyError);
  PolygonSoup open = test::cube_soup();
  open.offsets.pop_back();
  open.indices.resize(open.offsets.back());
  CHECK_THROWS_WITH_AS(polyhedron_to_hexahedra(build_mesh(open)), doctest::Contains("is a hole"),
                       TopologyError);
}

#pragma once
// Small meshes with closed-form counts, shared by the tests and the benchmarks (no doctest here).

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/cells/cell_complex.h>
#include <dlfl/polygon_soup.h>

namespace dlfl::test {

using Triangle = std::array<std::uint32_t, 3>;

/// A soup of the given positions and triangles (vertex indices, in this order).
inline PolygonSoup triangle_soup(std::vector<glm::dvec3> positions, const std::vector<Triangle>& triangles) {
  PolygonSoup s;
  s.positions = std::move(positions);
  for (const auto& t : triangles) s.add_face({t[0], t[1], t[2]});
  return s;
}

inline PolygonSoup tetrahedron_soup() {
  return triangle_soup({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
                       {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
}

/// The regular octahedron (vertices at the unit axis points): V = 6, E = 12, F = 8, every vertex 4-valent.
inline PolygonSoup octahedron_soup() {
  return triangle_soup(
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

/// The regular icosahedron: V = 12, E = 30, F = 20, every vertex 5-valent.
inline PolygonSoup icosahedron_soup() {
  const double p = std::numbers::phi;
  const std::vector<glm::dvec3> positions = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0},
                                             {0, -1, p}, {0, 1, p}, {0, -1, -p}, {0, 1, -p},
                                             {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  const std::vector<Triangle> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  return triangle_soup(positions, faces);
}

inline PolygonSoup cube_soup() {
  PolygonSoup s;
  for (int i = 0; i < 8; ++i)
    s.positions.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  s.add_face({0, 2, 3, 1});  // z = -1, normal -z
  s.add_face({4, 5, 7, 6});  // z = +1
  s.add_face({0, 1, 5, 4});  // y = -1
  s.add_face({2, 6, 7, 3});  // y = +1
  s.add_face({0, 4, 6, 2});  // x = -1
  s.add_face({1, 3, 7, 5});  // x = +1
  return s;
}

/// An n x m grid of quads wrapped both ways onto a torus: V = nm, E = 2nm, F = nm, genus 1.
inline PolygonSoup torus_soup(int n, int m, double major = 2.0, double minor = 0.5) {
  PolygonSoup s;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
      s.positions.push_back({(major + minor * std::cos(v)) * std::cos(u),
                             (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v)});
    }
  }
  auto id = [&](int i, int j) { return std::uint32_t(((i + n) % n) * m + (j + m) % m); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  return s;
}

/// A slab over a (2g+1) x 3 grid of unit cells with g cells punched out: a closed surface of genus g.
/// Built by thickening: top quads, reversed bottom quads, and a side quad on every boundary edge of the
/// region.
inline PolygonSoup genus_soup(int g) {
  const int nx = 2 * g + 1, ny = 3;
  auto present = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < nx && j < ny && !(j == 1 && i % 2 == 1);
  };
  PolygonSoup s;
  auto top = [&](int i, int j) { return std::uint32_t(j * (nx + 1) + i); };
  const std::uint32_t layer = std::uint32_t((nx + 1) * (ny + 1));
  auto bottom = [&](int i, int j) { return layer + top(i, j); };
  for (int z = 0; z < 2; ++z) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) s.positions.push_back({double(i), double(j), z == 0 ? 1.0 : 0.0});
    }
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (!present(i, j)) continue;
      s.add_face({top(i, j), top(i + 1, j), top(i + 1, j + 1), top(i, j + 1)});
      s.add_face({bottom(i, j + 1), bottom(i + 1, j + 1), bottom(i + 1, j), bottom(i, j)});
      // The cell's four edges in counter-clockwise order, with the neighbour across each.
      const int corners[5][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}, {i, j}};
      const int across[4][2] = {{i, j - 1}, {i + 1, j}, {i, j + 1}, {i - 1, j}};
      for (int k = 0; k < 4; ++k) {
        if (present(across[k][0], across[k][1])) continue;
        auto [pi, pj] = corners[k];
        auto [qi, qj] = corners[k + 1];
        s.add_face({top(qi, qj), top(pi, pj), bottom(pi, pj), bottom(qi, qj)});
      }
    }
  }
  return s;
}

/// A flat n x m grid of quads: an open mesh with one boundary loop.
inline PolygonSoup grid_soup(int n, int m) {
  PolygonSoup s;
  for (int j = 0; j <= m; ++j) {
    for (int i = 0; i <= n; ++i) s.positions.push_back({double(i), double(j), 0.0});
  }
  auto id = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  return s;
}

/// Adds the faces of an n-gonal prism to `s`, whose positions are the bottom ring (0 .. n-1) and then the top
/// ring (n .. 2n-1), both counter-clockwise seen from above: the two n-gons and n side quads, outward.
inline void add_prism_faces(PolygonSoup& s, int n) {
  std::vector<std::uint32_t> bottom, top;
  for (int i = 0; i < n; ++i) {
    bottom.push_back(std::uint32_t(n - 1 - i));
    top.push_back(std::uint32_t(n + i));
  }
  s.add_face(bottom);
  s.add_face(top);
  for (int i = 0; i < n; ++i) {
    const auto a = std::uint32_t(i), b = std::uint32_t((i + 1) % n);
    s.add_face({a, b, std::uint32_t(n + b), std::uint32_t(n + a)});
  }
}

/// A soup of quads (faces as cycles a b c d) as a cell complex of tensor-product quads (a, b, d, c).
inline CellComplex quads_of(const PolygonSoup& soup) {
  CellComplex c;
  c.positions = soup.positions;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto q = soup.face(f);
    if (q.size() != 4) throw std::invalid_argument("quads_of: face " + std::to_string(f) + " is no quad");
    c.add_cell({q[0], q[1], q[3], q[2]});
  }
  return c;
}

inline Mesh tetrahedron() { return build_mesh(tetrahedron_soup()); }
inline Mesh cube() { return build_mesh(cube_soup()); }

}  // namespace dlfl::test

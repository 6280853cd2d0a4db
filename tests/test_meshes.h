#pragma once
// Small meshes with closed-form counts, shared by the tests.

#include <cmath>
#include <numbers>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/polygon_soup.h>

namespace dlfl::test {

inline PolygonSoup tetrahedron_soup() {
  PolygonSoup s;
  s.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  s.add_face({0, 1, 2});
  s.add_face({0, 3, 1});
  s.add_face({0, 2, 3});
  s.add_face({1, 3, 2});
  return s;
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

inline Mesh tetrahedron() { return build_mesh(tetrahedron_soup()); }
inline Mesh cube() { return build_mesh(cube_soup()); }

}  // namespace dlfl::test

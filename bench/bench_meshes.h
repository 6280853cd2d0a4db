#pragma once
// The input meshes of the benchmarks: torus grids of any size, closed and regular (every vertex 4-valent, or
// 6-valent when triangulated), so figures from different benchmarks compare.

#include <cmath>
#include <cstdint>
#include <numbers>

#include <dlfl/polygon_soup.h>

namespace dlfl::bench {

/// An n x m torus grid (major radius 2, minor 0.5) of quads, or of triangles (each quad cut along a
/// diagonal), counter-clockwise seen from outside.
inline PolygonSoup torus_soup(int n, int m, bool triangles = false) {
  PolygonSoup s;
  s.positions.reserve(std::size_t(n) * m);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
      s.positions.push_back(
          {(2 + 0.5 * std::cos(v)) * std::cos(u), (2 + 0.5 * std::cos(v)) * std::sin(u), 0.5 * std::sin(v)});
    }
  }
  const std::size_t faces = std::size_t(n) * m * (triangles ? 2 : 1);
  s.indices.reserve(faces * (triangles ? 3 : 4));
  s.offsets.reserve(faces + 1);
  auto id = [&](int i, int j) { return std::uint32_t((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      if (triangles) {
        s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  }
  return s;
}

}  // namespace dlfl::bench

#pragma once
// The inputs of the lateral-artifact measurements (docs/lateral_artifacts.md), doctest-free so that the
// table program in bench/ builds them too: convex shapes whose flat sides are split into several faces, the
// honeycomb's bricklayers' problem, and smooth shapes.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <glm/vec3.hpp>

#include <dlfl/polygon_soup.h>

namespace dlfl::test {

/// An n-gonal prism of radius 1 and height `height` whose sides are each split into `rows` quads stacked
/// along the height, capped by two n-gons: V = n (rows + 1), E = n (2 rows + 1), F = n rows + 2. Convex, all
/// faces planar; with rows > 1 the quads of a side are coplanar.
inline PolygonSoup prism_rows_soup(int n, int rows, double height = 3.0) {
  PolygonSoup s;
  for (int z = 0; z <= rows; ++z) {
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      s.positions.push_back({std::cos(a), std::sin(a), height * z / rows});
    }
  }
  const auto at = [n](int z, int i) { return std::uint32_t(z * n + (i % n)); };
  std::vector<std::uint32_t> cap;
  for (int i = n - 1; i >= 0; --i) cap.push_back(at(0, i));  // the bottom, seen from below
  s.add_face(cap);
  cap.clear();
  for (int i = 0; i < n; ++i) cap.push_back(at(rows, i));
  s.add_face(cap);
  for (int z = 0; z < rows; ++z) {
    for (int i = 0; i < n; ++i) s.add_face({at(z, i), at(z, i + 1), at(z + 1, i + 1), at(z + 1, i)});
  }
  return s;
}

/// The box [0, a] x [0, b] x [0, c] with every side split into unit squares (a, b, c >= 1): a grid of
/// a x b, b x c or a x c quads per side. V = 2 (ab + bc + ca) + 2, E = 4 (ab + bc + ca), F = 2 (ab + bc +
/// ca).
inline PolygonSoup box_grid_soup(int a, int b, int c) {
  PolygonSoup s;
  // One index per lattice point on the surface, made on first use.
  std::vector<std::int64_t> index(std::size_t((a + 1) * (b + 1) * (c + 1)), -1);
  const auto at = [&](int x, int y, int z) {
    std::int64_t& i = index[std::size_t((z * (b + 1) + y) * (a + 1) + x)];
    if (i < 0) {
      i = std::int64_t(s.positions.size());
      s.positions.push_back({double(x), double(y), double(z)});
    }
    return std::uint32_t(i);
  };
  // A side is the lattice points p + i u + j v (0 <= i <= nu, 0 <= j <= nv); u x v points outward.
  const auto side = [&](glm::ivec3 p, glm::ivec3 u, int nu, glm::ivec3 v, int nv) {
    for (int j = 0; j < nv; ++j) {
      for (int i = 0; i < nu; ++i) {
        const glm::ivec3 q = p + i * u + j * v;
        const glm::ivec3 r = q + u, t = q + u + v, w = q + v;
        s.add_face({at(q.x, q.y, q.z), at(r.x, r.y, r.z), at(t.x, t.y, t.z), at(w.x, w.y, w.z)});
      }
    }
  };
  const glm::ivec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1), O(0, 0, 0);
  side(O, Y, b, X, a);      // z = 0, outward -z
  side(c * Z, X, a, Y, b);  // z = c, outward +z
  side(O, X, a, Z, c);      // y = 0, outward -y
  side(b * Y, Z, c, X, a);  // y = b, outward +y
  side(O, Z, c, Y, b);      // x = 0, outward -x
  side(a * X, Y, b, Z, c);  // x = a, outward +x
  return s;
}

/// Every face of `s` split into triangles around its centroid (a new vertex per face, coplanar with it for
/// planar faces): F' = sum of the face sizes, V' = V + F, E' = E + sum of the face sizes.
inline PolygonSoup split_around_centroids(const PolygonSoup& s) {
  PolygonSoup out;
  out.positions = s.positions;
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    const auto face = s.face(f);
    glm::dvec3 centre(0.0);
    for (std::uint32_t v : face) centre += s.positions[v];
    const auto c = std::uint32_t(out.positions.size());
    out.positions.push_back(centre / double(face.size()));
    for (std::size_t i = 0; i < face.size(); ++i) out.add_face({face[i], face[(i + 1) % face.size()], c});
  }
  return out;
}

}  // namespace dlfl::test

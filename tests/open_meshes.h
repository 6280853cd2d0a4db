#pragma once
// Open meshes (with boundary loops) for the schemes' boundary rules, shared by the tests and the benchmarks
// (no doctest here).

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <utility>
#include <vector>

#include <dlfl/polygon_soup.h>

namespace dlfl::test {

/// A tube of radius `radius` around the z axis: `around` quads around, `rows` rows of height `row_height`,
/// both ends open. V = around (rows + 1), E = around (2 rows + 1), F = around rows; two boundary loops of
/// `around` edges, the first at z = 0 (vertices 0 .. around-1), the last at z = rows row_height.
inline PolygonSoup open_tube_soup(int around, int rows, double radius = 1.0, double row_height = 0.75) {
  PolygonSoup s;
  for (int r = 0; r <= rows; ++r) {
    for (int i = 0; i < around; ++i) {
      const double a = 2 * std::numbers::pi * i / around;
      s.positions.push_back({radius * std::cos(a), radius * std::sin(a), r * row_height});
    }
  }
  auto id = [&](int r, int i) { return std::uint32_t(r * around + (i + around) % around); };
  for (int r = 0; r < rows; ++r) {
    for (int i = 0; i < around; ++i) s.add_face({id(r, i), id(r, i + 1), id(r + 1, i + 1), id(r + 1, i)});
  }
  return s;
}

/// The faces of `soup` for which `keep(face index)` holds, with only the vertices they use (renumbered in
/// their old order), positions bit-identical.
inline PolygonSoup soup_part(const PolygonSoup& soup, const std::function<bool(std::size_t)>& keep) {
  std::vector<std::int64_t> new_index(soup.positions.size(), -1);
  std::vector<std::vector<std::uint32_t>> faces;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (!keep(f)) continue;
    const auto face = soup.face(f);
    faces.emplace_back(face.begin(), face.end());
    for (std::uint32_t v : face) new_index[v] = 0;
  }
  PolygonSoup part;
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    if (new_index[v] < 0) continue;
    new_index[v] = std::int64_t(part.positions.size());
    part.positions.push_back(soup.positions[v]);
  }
  for (auto& face : faces) {
    for (auto& v : face) v = std::uint32_t(new_index[v]);
    part.add_face(face);
  }
  return part;
}

/// The centroid of face f of the soup.
inline glm::dvec3 soup_face_centroid(const PolygonSoup& soup, std::size_t f) {
  glm::dvec3 sum(0.0);
  const auto face = soup.face(f);
  for (std::uint32_t v : face) sum += soup.positions[v];
  return sum / double(face.size());
}

/// A closed mesh cut in two along a loop of its edges that lies in the plane z = `cut_z` (the faces are on
/// either side of it): the faces whose centroid lies below, and those above. The two halves share the loop's
/// vertices, at bit-identical positions.
inline std::pair<PolygonSoup, PolygonSoup> halves_at_z(const PolygonSoup& closed, double cut_z = 0.0) {
  auto below = [&](std::size_t f) { return soup_face_centroid(closed, f).z < cut_z; };
  return {soup_part(closed, below), soup_part(closed, [&](std::size_t f) { return !below(f); })};
}

/// A closed tube (`open_tube_soup` with both ends capped by an `around`-gon), centred so that the ring of
/// `rows / 2` lies at z = 0 when rows is even: `halves_at_z` then cuts it into two open cups.
inline PolygonSoup capped_tube_soup(int around, int rows, double radius = 1.0, double row_height = 0.75) {
  PolygonSoup s = open_tube_soup(around, rows, radius, row_height);
  for (auto& p : s.positions) p.z -= rows / 2 * row_height;
  std::vector<std::uint32_t> bottom, top;
  for (int i = 0; i < around; ++i) {
    bottom.push_back(std::uint32_t(around - 1 - i));  // clockwise from above: facing down
    top.push_back(std::uint32_t(rows * around + i));
  }
  s.add_face(bottom);
  s.add_face(top);
  return s;
}

/// A flat n x m grid of unit quads in the plane z = 0 with the given cells (i, j) left out: one outer
/// boundary loop and one more per hole (holes must not touch each other or the border).
inline PolygonSoup grid_with_holes(int n, int m, const std::vector<std::pair<int, int>>& holes) {
  PolygonSoup s;
  for (int j = 0; j <= m; ++j) {
    for (int i = 0; i <= n; ++i) s.positions.push_back({double(i), double(j), 0.0});
  }
  auto id = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) {
      bool hole = false;
      for (const auto& [hi, hj] : holes) hole = hole || (hi == i && hj == j);
      if (!hole) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return s;
}

}  // namespace dlfl::test

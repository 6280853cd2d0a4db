#pragma once
// Runs CGAL's implementation of a classic scheme on the same mesh and compares results: every vertex position
// to 1e-12, and every face as a cycle of vertices. CGAL is an independent implementation of the same
// published rules.

#include <doctest/doctest.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <algorithm>
#include <map>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/mesh.h>

namespace dlfl::oracle {

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

inline SurfaceMesh to_cgal(const PolygonSoup& soup) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  for (const auto& p : soup.positions) v.push_back(sm.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    std::vector<SurfaceMesh::Vertex_index> face;
    for (auto k : soup.face(f)) face.push_back(v[k]);
    REQUIRE(sm.add_face(face) != SurfaceMesh::null_face());
  }
  return sm;
}

inline PolygonSoup from_cgal(const SurfaceMesh& sm) {
  PolygonSoup soup;
  std::map<SurfaceMesh::Vertex_index, std::uint32_t> index;
  for (auto v : sm.vertices()) {
    index[v] = static_cast<std::uint32_t>(soup.positions.size());
    const auto& p = sm.point(v);
    soup.positions.push_back({p.x(), p.y(), p.z()});
  }
  for (auto f : sm.faces()) {
    std::vector<std::uint32_t> face;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) face.push_back(index[v]);
    soup.add_face(face);
  }
  return soup;
}

// A face as a cycle starting at its smallest index, so equal cycles compare equal.
inline std::vector<std::uint32_t> canonical(std::vector<std::uint32_t> face) {
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
  return face;
}

/// Checks that `ours` and `theirs` are the same polygon mesh up to vertex numbering: a bijection of vertices
/// whose positions agree to `tolerance`, under which the faces (with orientation) are the same cycles.
inline void require_same(const PolygonSoup& ours, const PolygonSoup& theirs, double tolerance = 1e-12) {
  REQUIRE(ours.positions.size() == theirs.positions.size());
  REQUIRE(ours.num_faces() == theirs.num_faces());
  // Match vertices by position: sort both by x and pair up; the meshes here are small, so a nearest search
  // within the sorted order is enough to be robust against ties.
  const std::size_t n = ours.positions.size();
  std::vector<std::uint32_t> map(n, 0xFFFFFFFFu);
  std::vector<bool> taken(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    double best = 1e300;
    std::size_t best_j = n;
    for (std::size_t j = 0; j < n; ++j) {
      if (taken[j]) continue;
      const auto d = ours.positions[i] - theirs.positions[j];
      const double dist = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
      if (dist < best) {
        best = dist;
        best_j = j;
      }
    }
    REQUIRE(best_j < n);
    CHECK(best <= tolerance);
    taken[best_j] = true;
    map[i] = static_cast<std::uint32_t>(best_j);
  }
  std::vector<std::vector<std::uint32_t>> a, b;
  for (std::size_t f = 0; f < ours.num_faces(); ++f) {
    std::vector<std::uint32_t> face;
    for (auto k : ours.face(f)) face.push_back(map[k]);
    a.push_back(canonical(face));
  }
  for (std::size_t f = 0; f < theirs.num_faces(); ++f) {
    auto face = theirs.face(f);
    b.push_back(canonical({face.begin(), face.end()}));
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  CHECK(a == b);
}

}  // namespace dlfl::oracle

#pragma once
// The meshes every modeling-operation test runs on: genus 0 to 3, faces of 3 to 8 sides, an open mesh and
// two components. Each comes with its genus-independent facts, so a test can derive expected counts.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/mesh.h>

#include "test_meshes.h"

namespace dlfl::test {

struct ModelingMesh {
  std::string name;
  Mesh mesh;
};

/// An n-gonal prism of radius 1 and height 1: two n-gons and n quads (V = 2n, E = 3n, F = n + 2).
inline PolygonSoup prism_soup(int n) {
  PolygonSoup s;
  for (int z = 0; z < 2; ++z) {
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      s.positions.push_back({std::cos(a), std::sin(a), double(z)});
    }
  }
  add_prism_faces(s, n);
  return s;
}

/// The faces of `b` added to `a`, as a second component, its positions moved by `offset`.
inline PolygonSoup disjoint_union(PolygonSoup a, const PolygonSoup& b, const glm::dvec3& offset = {5, 0, 0}) {
  const auto base = static_cast<std::uint32_t>(a.positions.size());
  for (const auto& p : b.positions) a.positions.push_back(p + offset);
  for (std::size_t f = 0; f < b.num_faces(); ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t v : b.face(f)) face.push_back(v + base);
    a.add_face(face);
  }
  return a;
}

/// The ten meshes: tetrahedron (triangles), cube (quads), octahedron, pentagonal, hexagonal and octagonal
/// prisms (5-, 6- and 8-gons), a 4 x 3 torus (genus 1), the genus-2 and genus-3 slabs, an open 3 x 2 grid,
/// and a cube beside a tetrahedron (two components).
inline std::vector<ModelingMesh> modeling_meshes() {
  std::vector<ModelingMesh> out;
  out.push_back({"tetrahedron", build_mesh(tetrahedron_soup())});
  out.push_back({"cube", build_mesh(cube_soup())});
  out.push_back({"octahedron", build_mesh(octahedron_soup())});
  out.push_back({"pentagonal prism", build_mesh(prism_soup(5))});
  out.push_back({"hexagonal prism", build_mesh(prism_soup(6))});
  out.push_back({"octagonal prism", build_mesh(prism_soup(8))});
  out.push_back({"torus 4x3", build_mesh(torus_soup(4, 3))});
  out.push_back({"genus 2", build_mesh(genus_soup(2))});
  out.push_back({"genus 3", build_mesh(genus_soup(3))});
  out.push_back({"open grid 3x2", build_mesh(grid_soup(3, 2))});
  out.push_back({"cube and tetrahedron", build_mesh(disjoint_union(cube_soup(), tetrahedron_soup()))});
  return out;
}

}  // namespace dlfl::test

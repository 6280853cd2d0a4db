#pragma once
// Meshes for the subdivision-scheme tests, on top of test_meshes.h.

#include <array>
#include <cmath>
#include <numbers>

#include <dlfl/build_mesh.h>
#include <dlfl/mesh.h>
#include <dlfl/polygon_soup.h>
#include "test_meshes.h"

namespace dlfl::test {

/// The regular dodecahedron of data/dodecahedron.obj (circumradius sqrt(3), centred at the origin):
/// 20 vertices, 30 edges, 12 pentagons, counter-clockwise from outside.
inline PolygonSoup dodecahedron_soup() {
  const double phi = std::numbers::phi, inv = 1.0 / std::numbers::phi;
  PolygonSoup s;
  for (int i = 0; i < 8; ++i)
    s.positions.push_back({i & 4 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 1 ? 1.0 : -1.0});
  s.positions.insert(s.positions.end(), {{0, -inv, -phi},
                                         {-inv, -phi, 0},
                                         {-phi, 0, -inv},
                                         {0, -inv, phi},
                                         {-inv, phi, 0},
                                         {phi, 0, -inv},
                                         {0, inv, -phi},
                                         {inv, -phi, 0},
                                         {-phi, 0, inv},
                                         {0, inv, phi},
                                         {inv, phi, 0},
                                         {phi, 0, inv}});
  const std::array<std::array<std::uint32_t, 5>, 12> faces = {{{15, 9, 0, 8, 4},
                                                               {16, 10, 0, 9, 1},
                                                               {14, 8, 0, 10, 2},
                                                               {5, 11, 1, 9, 15},
                                                               {3, 12, 2, 10, 16},
                                                               {6, 13, 4, 8, 14},
                                                               {6, 14, 2, 12, 18},
                                                               {5, 15, 4, 13, 19},
                                                               {3, 16, 1, 11, 17},
                                                               {18, 12, 3, 17, 7},
                                                               {19, 13, 6, 18, 7},
                                                               {17, 11, 5, 19, 7}}};
  for (const auto& f : faces) s.add_face(f);
  return s;
}

inline Mesh dodecahedron() { return build_mesh(dodecahedron_soup()); }

/// A heptagonal prism (radius 1, z = -1 and z = 1) with faces of 3 to 7 sides, made with the kernel's
/// operators: the vertical edge at angle 0 is subdivided at its midpoint (its two quads become pentagons),
/// the bottom heptagon is cut by the diagonal b1-b6 into a triangle (b0 b1 b6) and a hexagon, and the quad
/// between angles 3 and 4 by a diagonal into two triangles. Faces: 1 heptagon, 1 hexagon, 2 pentagons,
/// 4 quads, 3 triangles; V = 15, E = 24, F = 11; genus 0; every face planar, but not strictly convex (the
/// subdivided vertical edge is straight, and each cut face lies in the plane of its neighbour).
inline Mesh mixed_polyhedron() {
  PolygonSoup s;
  const int n = 7;
  for (int z = 0; z < 2; ++z) {
    for (int i = 0; i < n; ++i) {
      const double u = 2 * std::numbers::pi * i / n;
      s.positions.push_back({std::cos(u), std::sin(u), z == 0 ? -1.0 : 1.0});
    }
  }
  auto bottom = [](int i) { return std::uint32_t(i % 7); };
  auto top = [](int i) { return std::uint32_t(7 + i % 7); };
  s.add_face({bottom(0), bottom(6), bottom(5), bottom(4), bottom(3), bottom(2), bottom(1)});  // normal -z
  s.add_face({top(0), top(1), top(2), top(3), top(4), top(5), top(6)});                       // normal +z
  for (int i = 0; i < n; ++i) s.add_face({bottom(i), bottom(i + 1), top(i + 1), top(i)});
  Mesh m = build_mesh(s);
  // build_mesh numbers vertex i as VertexId(i) and face i as FaceId(i).
  auto corner_at = [&](FaceId f, VertexId v) {
    for (CornerId c : m.corners(f)) {
      if (m.vertex(c) == v) return c;
    }
    return CornerId();
  };
  for (EdgeId e : m.edges()) {
    const VertexId a = m.from(e), b = m.to(e);
    if ((a == VertexId(bottom(0)) && b == VertexId(top(0))) ||
        (a == VertexId(top(0)) && b == VertexId(bottom(0)))) {
      m.subdivide_edge(e, {1.0, 0.0, 0.0});
      break;
    }
  }
  m.insert_edge(corner_at(FaceId(0), VertexId(bottom(1))), corner_at(FaceId(0), VertexId(bottom(6))));
  const FaceId quad3(2 + 3);  // bottom(3), bottom(4), top(4), top(3)
  m.insert_edge(corner_at(quad3, VertexId(bottom(3))), corner_at(quad3, VertexId(top(4))));
  return m;
}

}  // namespace dlfl::test

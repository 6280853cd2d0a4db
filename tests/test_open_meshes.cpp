// The open meshes of tests/open_meshes.h have the counts and boundary loops their comments promise.
#include <doctest/doctest.h>

#include <dlfl/build_mesh.h>
#include <dlfl/validate.h>

#include "open_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {
// V, E and F without hole faces, and the number of hole faces (boundary loops).
struct OpenCounts {
  std::size_t vertices, edges, faces, loops;
  bool operator==(const OpenCounts&) const = default;
};
OpenCounts open_counts(const Mesh& m) {
  return {m.num_vertices(), m.num_edges(), m.num_surface_faces(), m.num_hole_faces()};
}
}  // namespace

TEST_CASE("open meshes: tubes, halves and grids with holes have their closed-form counts") {
  const Mesh tube = build_mesh(open_tube_soup(8, 3));
  CHECK(validate(tube).valid());
  CHECK(open_counts(tube) == OpenCounts{8 * 4, 8 * 7, 8 * 3, 2});

  // The capped tube is closed: a cylinder, V - E + F = 2.
  const PolygonSoup capped = capped_tube_soup(6, 4);
  const Mesh closed = build_mesh(capped);
  CHECK(validate(closed).valid());
  CHECK(open_counts(closed) == OpenCounts{6 * 5, 6 * 9, 6 * 4 + 2, 0});
  // Cut at z = 0 (the ring of row 2): two cups, each a cap, two rows and the 6 ring vertices shared.
  const auto [below, above] = halves_at_z(capped);
  for (const PolygonSoup* half : {&below, &above}) {
    const Mesh cup = build_mesh(*half);
    CHECK(validate(cup).valid());
    CHECK(open_counts(cup) == OpenCounts{6 * 3, 6 * 5, 6 * 2 + 1, 1});
  }

  // A 5 x 4 grid without cells (1, 1) and (3, 2): 30 vertices, 49 edges, 18 quads, three loops.
  const Mesh holed = build_mesh(grid_with_holes(5, 4, {{1, 1}, {3, 2}}));
  CHECK(validate(holed).valid());
  CHECK(open_counts(holed) == OpenCounts{30, 49, 18, 3});
}

// The classic schemes agree with CGAL's Subdivision_method_3 on closed meshes: positions to 1e-12, faces
// exactly.

#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "../scheme_meshes.h"
#include "../test_meshes.h"
#include "cgal_compare.h"
#include "schemes/catmull_clark.h"

using namespace dlfl;
using namespace dlfl::oracle;

namespace {
std::vector<PolygonSoup> closed_meshes() {
  return {test::tetrahedron_soup(), test::cube_soup(), test::dodecahedron_soup(), test::torus_soup(6, 5),
          test::genus_soup(2)};
}
}  // namespace

TEST_CASE("oracle: catmull-clark agrees with CGAL on closed meshes") {
  for (const PolygonSoup& soup : closed_meshes()) {
    CAPTURE(soup.num_faces());
    SurfaceMesh sm = to_cgal(soup);
    CGAL::Subdivision_method_3::CatmullClark_subdivision(sm, CGAL::parameters::number_of_iterations(2));
    const Mesh ours = catmull_clark(catmull_clark(build_mesh(soup)));
    require_same(to_polygons(ours), from_cgal(sm));
  }
}

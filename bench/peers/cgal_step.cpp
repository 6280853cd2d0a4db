// One step of CGAL's Subdivision_method_3 on a Surface_mesh, timed alone (peer_steps.h). The kernel is
// Simple_cartesian<double>: subdivision only constructs points, so a filtered kernel would add nothing but
// cost.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <vector>

#include "peer_steps.h"

namespace dlfl::bench {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

SurfaceMesh to_surface_mesh(const PolygonSoup& soup) {
  SurfaceMesh m;
  m.reserve(SurfaceMesh::size_type(soup.positions.size()), SurfaceMesh::size_type(soup.indices.size() / 2),
            SurfaceMesh::size_type(soup.num_faces()));
  for (const auto& p : soup.positions) m.add_vertex(Kernel::Point_3(p.x, p.y, p.z));
  std::vector<SurfaceMesh::Vertex_index> face;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    face.clear();
    for (std::uint32_t v : soup.face(f)) face.emplace_back(v);
    m.add_face(face);
  }
  return m;
}

}  // namespace

std::optional<StepResult> cgal_step(Scheme scheme, const PolygonSoup& input) {
  namespace sm3 = CGAL::Subdivision_method_3;
  if (scheme == Scheme::honeycomb) return std::nullopt;
  SurfaceMesh m = to_surface_mesh(input);
  const std::size_t input_faces = m.number_of_faces();
  const auto one = CGAL::parameters::number_of_iterations(1);
  const StepCost cost = measure_step([&] {
    switch (scheme) {
      case Scheme::catmull_clark:
        sm3::CatmullClark_subdivision(m, one);
        break;
      case Scheme::loop:
        sm3::Loop_subdivision(m, one);
        break;
      case Scheme::sqrt3:
        sm3::Sqrt3_subdivision(m, one);
        break;
      case Scheme::doo_sabin:
        sm3::DooSabin_subdivision(m, one);
        break;
      case Scheme::honeycomb:
        break;
    }
  });
  return StepResult{cost, input_faces, m.number_of_faces()};
}

}  // namespace dlfl::bench

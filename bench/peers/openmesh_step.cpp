// One step of OpenMesh's uniform subdividers, timed alone (peer_steps.h): Catmull-Clark on a polygon mesh,
// Loop and sqrt3 on a triangle mesh. OpenMesh has no Doo-Sabin or honeycomb subdivider.

#include "openmesh_types.h"  // before the subdividers, which need the mesh types declared

#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>
#include <vector>

#include "peer_steps.h"

namespace dlfl::bench {

namespace {

template <class OmMesh>
OmMesh to_openmesh(const PolygonSoup& soup) {
  OmMesh m;
  m.reserve(soup.positions.size(), soup.indices.size() / 2, soup.num_faces());
  for (const auto& p : soup.positions) m.add_vertex(typename OmMesh::Point(p.x, p.y, p.z));
  std::vector<typename OmMesh::VertexHandle> face;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    face.clear();
    for (std::uint32_t v : soup.face(f)) face.emplace_back(int(v));
    m.add_face(face);
  }
  return m;
}

// Times the whole call, as for CGAL: preparing the subdivider's properties, the step, and releasing them.
template <class Subdivider, class OmMesh>
StepResult run(const PolygonSoup& input) {
  OmMesh m = to_openmesh<OmMesh>(input);
  const std::size_t input_faces = m.n_faces();
  Subdivider subdivider;
  const StepCost cost = measure_step([&] { subdivider(m, 1); });
  return StepResult{cost, input_faces, m.n_faces()};
}

}  // namespace

std::optional<StepResult> openmesh_step(Scheme scheme, const PolygonSoup& input) {
  namespace uniform = OpenMesh::Subdivider::Uniform;
  switch (scheme) {
    case Scheme::catmull_clark:
      return run<uniform::CatmullClarkT<OmPolyMesh>, OmPolyMesh>(input);
    case Scheme::loop:
      return run<uniform::LoopT<OmTriMesh>, OmTriMesh>(input);
    case Scheme::sqrt3:
      return run<uniform::Sqrt3T<OmTriMesh>, OmTriMesh>(input);
    case Scheme::doo_sabin:
    case Scheme::honeycomb:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace dlfl::bench

// planarize: see planarize.h.

#include <dlfl/operations/planarize.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include <dlfl/navigation.h>
#include <dlfl/operations/detail/best_fit_plane.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {

// Below this a face counts as planar (relative to its mean edge length): rounding leaves about 1e-16.
constexpr double planar_tolerance = 1e-12;

bool counts(const Mesh& m, FaceId f) { return !m.is_hole(f) && m.size(f) >= 4; }

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// One round; true if a vertex moved.
bool planarize_round(Transaction& tx) {
  const Mesh& m = tx.mesh();
  std::vector<glm::dvec3> shift(m.vertex_capacity(), glm::dvec3(0.0));
  std::vector<std::uint32_t> planes(m.vertex_capacity(), 0);
  for (FaceId f : surface_faces(m)) {
    if (!counts(m, f)) continue;
    const detail::Plane plane = detail::best_fit_plane(m, f);
    const bool planar = detail::face_nonplanarity(m, f, plane) <= planar_tolerance;
    for (VertexId v : vertices(m, f)) {
      ++planes[v.index()];
      if (!planar) shift[v.index()] -= plane.normal * glm::dot(plane.normal, m.position(v) - plane.point);
    }
  }
  std::vector<std::pair<VertexId, glm::dvec3>> moves;
  for (VertexId v : m.vertices()) {
    if (planes[v.index()] == 0 || shift[v.index()] == glm::dvec3(0.0)) continue;
    const glm::dvec3 to = m.position(v) + shift[v.index()] / double(planes[v.index()]);
    if (finite(to) && to != m.position(v)) moves.emplace_back(v, to);
  }
  for (const auto& [v, to] : moves) tx.set_position(v, to);
  return !moves.empty();
}

}  // namespace

double nonplanarity(const Mesh& m) {
  double largest = 0.0;
  for (FaceId f : surface_faces(m)) {
    if (counts(m, f))
      largest = std::max(largest, detail::face_nonplanarity(m, f, detail::best_fit_plane(m, f)));
  }
  return largest;
}

void check_planarize(const PlanarizeOptions& o) {
  if (o.iterations < 0 || o.iterations > 10000) {
    detail::refuse_worded("planarize", "iterations",
                          " = " + std::to_string(o.iterations) + " is outside [0, 10000]");
  }
}

PlanarizeResult planarize(Transaction& tx, const PlanarizeOptions& options) {
  check_planarize(options);
  PlanarizeResult r;
  r.nonplanarity_before = nonplanarity(tx.mesh());
  for (int i = 0; i < options.iterations && planarize_round(tx); ++i) ++r.iterations_run;
  r.nonplanarity_after = r.iterations_run == 0 ? r.nonplanarity_before : nonplanarity(tx.mesh());
  return r;
}

std::vector<OperationSpec> detail::planarize_operation_specs() {
  return {edit_operation(
      "planarize",
      "moves vertices towards their faces' least-squares planes; reports the non-planarity before and after",
      {param("iterations", ParamType::integer, 10, "rounds of moves (0: measure only)").in(0, 10000)},
      "V+0, E+0, F+0",
      [](Transaction& tx, const Params& p) {
        const PlanarizeResult r = planarize(tx, {static_cast<int>(p.integer("iterations"))});
        return Params{{"nonplanarity_before", r.nonplanarity_before},
                      {"nonplanarity_after", r.nonplanarity_after},
                      {"iterations_run", r.iterations_run}};
      },
      [](const Mesh&, Params& p) { check_planarize({static_cast<int>(p.integer("iterations"))}); })};
}
}  // namespace dlfl

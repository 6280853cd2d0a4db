// planarize: see planarize.h.

#include <dlfl/operations/planarize.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include <dlfl/analysis/detail/best_fit_plane.h>
#include <dlfl/analysis/detail/planarize_moves.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {

bool counts(const Mesh& m, FaceId f) { return !m.is_hole(f) && m.size(f) >= 4; }

// One round; true if a vertex moved.
bool planarize_round(Transaction& tx) {
  const std::vector<std::pair<VertexId, glm::dvec3>> moves = detail::planarize_moves(tx.mesh());
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

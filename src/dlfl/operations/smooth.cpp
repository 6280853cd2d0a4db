// smooth: see smooth.h.

#include <dlfl/operations/smooth.h>

#include <cmath>
#include <string>
#include <vector>

#include <dlfl/format.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

void smooth_round(Transaction& tx, const SmoothOptions& o) {
  const Mesh& m = tx.mesh();
  std::vector<std::pair<VertexId, glm::dvec3>> moves;
  for (VertexId v : m.vertices()) {
    if (m.is_point_sphere(v) || (o.keep_boundary && is_boundary(m, v))) continue;
    glm::dvec3 sum(0.0);
    double n = 0;
    for (VertexId w : neighbours(m, v)) {
      sum += m.position(w);
      ++n;
    }
    const glm::dvec3& p = m.position(v);
    const glm::dvec3 to = p + o.lambda * (sum / n - p);
    if (finite(to) && to != p) moves.emplace_back(v, to);
  }
  // Written after all are computed: every new position comes from the old ones.
  for (const auto& [v, to] : moves) tx.set_position(v, to);
}

SmoothOptions options_of(const Params& p) {
  return {static_cast<int>(p.integer("iterations")), p.number("lambda"), p.boolean("keep_boundary")};
}

}  // namespace

void check_smooth(const SmoothOptions& o) {
  if (o.iterations < 0 || o.iterations > 10000) {
    detail::refuse_worded("smooth", "iterations",
                          " = " + std::to_string(o.iterations) + " is outside [0, 10000]");
  }
  if (!std::isfinite(o.lambda)) detail::refuse_worded("smooth", "lambda", " is not finite");
  if (!(o.lambda > 0.0 && o.lambda <= 1.0)) {
    detail::refuse_worded("smooth", "lambda", " = " + format_number(o.lambda) + " is outside (0, 1]");
  }
}

void smooth(Transaction& tx, const SmoothOptions& options) {
  check_smooth(options);
  for (int i = 0; i < options.iterations; ++i) smooth_round(tx, options);
}

std::vector<OperationSpec> detail::smooth_operation_specs() {
  return {edit_operation(
      "smooth",
      "Laplacian smoothing: each vertex moves lambda of the way to the mean of its neighbours, per round",
      {param("iterations", ParamType::integer, 1, "rounds").in(0, 10000),
       param("lambda", ParamType::number, 0.5, "the share of the way to the neighbours' mean")
           .range(0, 1, true, false),
       param("keep_boundary", ParamType::boolean, true, "leave the vertices next to a hole face in place")},
      "V+0, E+0, F+0",
      [](Transaction& tx, const Params& p) {
        smooth(tx, options_of(p));
        return Params{};
      },
      [](const Mesh&, Params& p) { check_smooth(options_of(p)); })};
}
}  // namespace dlfl

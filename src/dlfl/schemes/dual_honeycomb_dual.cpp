#include <dlfl/schemes/dual_honeycomb_dual.h>

#include <string>

#include <dlfl/errors.h>
#include <dlfl/schemes/detail/corner_origins.h>
#include <dlfl/schemes/detail/honeycomb_params.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/scheme_table.h>
#include <dlfl/schemes/dual.h>

namespace dlfl {

Mesh dual_honeycomb_dual(const Mesh& mesh, const HoneycombParams& p, Origins* origins) {
  Mesh d;
  Origins dual_origins;
  std::vector<Origin> dual_corners;  // the honeycomb's origins name corners of the first dual
  try {
    d = detail::dual(mesh, p.boundary, origins ? &dual_origins : nullptr, origins ? &dual_corners : nullptr);
  } catch (const TopologyError& e) {
    throw TopologyError(std::string("dual-honeycomb-dual: ") + e.what());
  }
  // The first dual marks the boundary vertices it keeps, and the later steps keep those marks only: the
  // honeycomb leaves every other boundary vertex with two edges, which are no corners.
  HoneycombParams inner = p;
  inner.boundary.sharp_corners = false;
  try {
    check_honeycomb_params(d, inner);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(
        std::string("dual-honeycomb-dual: ") + e.what() +
        " (the honeycomb step runs on the dual, whose N-sided faces are the input's N-valent "
        "vertices)");
  }
  if (!origins) return dual(honeycomb(d, inner), inner.boundary);
  Origins honeycomb_origins;
  const Mesh h = honeycomb(d, inner, &honeycomb_origins);
  Mesh result = dual(h, inner.boundary, origins);
  detail::compose(honeycomb_origins, dual_origins, dual_corners);
  detail::compose(*origins, honeycomb_origins, {});
  return result;
}

namespace detail {

SchemeSpec dual_honeycomb_dual_scheme() {
  return {"dual-honeycomb-dual",
          "root-3 subdivision as dual(honeycomb(dual(mesh))): triangles on any polygon mesh",
          honeycomb_param_specs(),
          [](const Params& given, Params& resolved) {
            check_honeycomb_param_set("dual-honeycomb-dual", given, resolved);
          },
          [](const Mesh& m, const Params& p, Origins* origins) {
            return dual_honeycomb_dual(m, honeycomb_params_from(p), origins);
          },
          // V' = V + F, E' = 3E, F' = 2E
          [](const MeshCounts& c, const Params&) {
            return MeshCounts{c.vertices + c.faces, 3 * c.edges, 2 * c.edges};
          }};
}

}  // namespace detail
}  // namespace dlfl

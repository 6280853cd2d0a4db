#pragma once
// Internal to the scheme registry: the declaration of every scheme, each defined in the scheme's own .cpp
// next to its implementation. scheme_registry.cpp lists them; adding a scheme is one new file plus one line
// there and a name here.

#include <string>
#include <utility>

#include <dlfl/schemes/detail/boundary_params.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl::detail {

/// The declaration of a scheme without parameters, whose step is `step(mesh, origins)` and whose closed-form
/// counts are `counts`.
inline SchemeSpec parameterless_scheme(Mesh (*step)(const Mesh&, Origins*), std::string name, std::string doc,
                                       MeshCounts (*counts)(const MeshCounts&)) {
  SchemeSpec spec;
  spec.name = std::move(name);
  spec.doc = std::move(doc);
  spec.apply = [step](const Mesh& mesh, const Params&, Origins* origins) { return step(mesh, origins); };
  spec.counts = [counts](const MeshCounts& c, const Params&) { return counts(c); };
  return spec;
}

/// The declaration of a scheme whose parameters are the boundary options (`boundary` and `sharp_corners`,
/// boundary_params.h), whose step is `step(mesh, options, origins)` and whose closed-form counts are
/// `counts`.
inline SchemeSpec boundary_scheme(Mesh (*step)(const Mesh&, const BoundaryOptions&, Origins*),
                                  std::string name, std::string doc,
                                  MeshCounts (*counts)(const MeshCounts&)) {
  // Name, doc and counts as a scheme without parameters; then the parameters and a step that reads them.
  SchemeSpec spec = parameterless_scheme(nullptr, std::move(name), std::move(doc), counts);
  spec.params = boundary_param_specs();
  spec.apply = [step](const Mesh& mesh, const Params& params, Origins* origins) {
    return step(mesh, boundary_options_from(params), origins);
  };
  return spec;
}

/// The closed-form counts shared by several schemes (each scheme's header derives them).
inline MeshCounts honeycomb_counts(const MeshCounts& c) {  // V' = 2E, E' = 3E, F' = F + V
  return {2 * c.edges, 3 * c.edges, c.faces + c.vertices};
}
inline MeshCounts mp_honeycomb_counts(const MeshCounts& c) {  // V' = V + 2E, E' = 4E, F' = F + E
  return {c.vertices + 2 * c.edges, 4 * c.edges, c.faces + c.edges};
}
inline MeshCounts mp_pushing_counts(const MeshCounts& c) {  // V' = V + E, E' = 4E, F' = F + 2E
  return {c.vertices + c.edges, 4 * c.edges, c.faces + 2 * c.edges};
}

// Named after their files (loop_scheme in loop.cpp), but for mhp_scheme (meng_prautzsch_mixed.cpp),
// mlca_scheme (mlca_polygons.cpp) and mp_honeycomb_scheme, mp_pushing_scheme (meng_prautzsch_honeycomb.cpp,
// meng_prautzsch_pushing.cpp).
SchemeSpec catmull_clark_scheme(), doo_sabin_scheme(), dual_scheme(), dual_honeycomb_dual_scheme(),
    honeycomb_scheme(), loop_scheme(), mhp_scheme(), mlca_scheme(), mp_honeycomb_scheme(),
    mp_pushing_scheme(), sqrt3_scheme(), zhang_wang_honeycomb_scheme();

}  // namespace dlfl::detail

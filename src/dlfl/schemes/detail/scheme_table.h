#pragma once
// Internal to the scheme registry: the declaration of every scheme, each defined in the scheme's own .cpp
// next to its implementation. scheme_registry.cpp lists them; adding a scheme is one new file plus one line
// there and a name here.

#include <string>
#include <utility>

#include <dlfl/schemes/scheme_registry.h>

namespace dlfl::detail {

/// The declaration of a scheme without parameters, whose step is `step(mesh, origins)`.
inline SchemeSpec parameterless_scheme(Mesh (*step)(const Mesh&, Origins*), std::string name,
                                       std::string doc) {
  SchemeSpec spec;
  spec.name = std::move(name);
  spec.doc = std::move(doc);
  spec.apply = [step](const Mesh& mesh, const Params&, Origins* origins) { return step(mesh, origins); };
  return spec;
}

// Named after their files (loop_scheme in loop.cpp), but for mhp_scheme (meng_prautzsch_mixed.cpp),
// mlca_scheme (mlca_polygons.cpp) and mp_honeycomb_scheme, mp_pushing_scheme (meng_prautzsch_honeycomb.cpp,
// meng_prautzsch_pushing.cpp).
SchemeSpec catmull_clark_scheme(), doo_sabin_scheme(), dual_scheme(), dual_honeycomb_dual_scheme(),
    honeycomb_scheme(), loop_scheme(), mhp_scheme(), mlca_scheme(), mp_honeycomb_scheme(),
    mp_pushing_scheme(), sqrt3_scheme(), zhang_wang_honeycomb_scheme();

}  // namespace dlfl::detail

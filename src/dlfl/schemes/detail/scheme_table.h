#pragma once
// Internal to the scheme registry: the declaration of every scheme, each defined in the scheme's own .cpp
// next to its implementation. scheme_registry.cpp lists them; adding a scheme is one new file plus one line
// there and one here.

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

SchemeSpec catmull_clark_scheme();         // catmull_clark.cpp
SchemeSpec doo_sabin_scheme();             // doo_sabin.cpp
SchemeSpec dual_scheme();                  // dual.cpp
SchemeSpec dual_honeycomb_dual_scheme();   // dual_honeycomb_dual.cpp
SchemeSpec honeycomb_scheme();             // honeycomb.cpp
SchemeSpec loop_scheme();                  // loop.cpp
SchemeSpec mhp_scheme();                   // meng_prautzsch_mixed.cpp
SchemeSpec mlca_scheme();                  // mlca_polygons.cpp
SchemeSpec mp_honeycomb_scheme();          // meng_prautzsch_honeycomb.cpp
SchemeSpec mp_pushing_scheme();            // meng_prautzsch_pushing.cpp
SchemeSpec sqrt3_scheme();                 // sqrt3.cpp
SchemeSpec zhang_wang_honeycomb_scheme();  // zhang_wang_honeycomb.cpp

}  // namespace dlfl::detail

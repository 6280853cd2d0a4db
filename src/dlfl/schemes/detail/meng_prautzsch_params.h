#pragma once
// Internal to the schemes: the parameters that the Meng-Prautzsch schemes H, P and MHP share (the centre and
// the random choices), as data and as the structs the scheme functions take.

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <dlfl/parameters.h>
#include <dlfl/schemes/detail/meng_prautzsch_common.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl::detail {

/// center (a point, or the keyword "centroid"), random, epsilon, seed.
std::vector<ParamSpec> mp_shared_param_specs();

/// The centre of a resolved set: none for "centroid" (the scheme takes the vertex centroid).
std::optional<glm::dvec3> mp_center_from(const Params& resolved);

/// The random choices of a resolved set.
MpRandomChoice mp_random_from(const Params& resolved);

/// A step's tau, in (0, 1), and ratio, in (0, inf), with the defaults of MpStepParams, declared under the
/// given names ("tau" and "ratio"; MHP has one pair per kind of step).
std::vector<ParamSpec> mp_step_param_specs(const char* tau, std::string tau_doc, const char* ratio,
                                           std::string ratio_doc);

/// A step's parameters from a resolved set: tau and ratio under the given names, the centre and the random
/// choices.
MpStepParams mp_step_params_from(const Params& resolved, const char* tau, const char* ratio);

/// The declaration of H or P: tau and ratio, then the shared parameters; `step` (`mp_honeycomb` or
/// `mp_pushing`) runs on them.
template <class StepParams>
SchemeSpec mp_step_scheme(Mesh (*step)(const Mesh&, const StepParams&, Origins*), std::string name,
                          std::string doc, std::string tau_doc, std::string ratio_doc,
                          MeshCounts (*counts)(const MeshCounts&)) {
  SchemeSpec spec;
  spec.name = std::move(name);
  spec.doc = std::move(doc);
  spec.params = mp_step_param_specs("tau", std::move(tau_doc), "ratio", std::move(ratio_doc));
  for (ParamSpec& s : mp_shared_param_specs()) spec.params.push_back(std::move(s));
  spec.apply = [step](const Mesh& mesh, const Params& p, Origins* origins) {
    return step(mesh, StepParams{mp_step_params_from(p, "tau", "ratio")}, origins);
  };
  spec.counts = [counts](const MeshCounts& c, const Params&) { return counts(c); };
  return spec;
}

}  // namespace dlfl::detail

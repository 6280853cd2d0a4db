#pragma once
// Internal to the schemes: the parameters that the Meng-Prautzsch schemes H, P and MHP share (the centre and
// the random choices), as data and as the structs the scheme functions take.

#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include <dlfl/parameters.h>
#include <dlfl/schemes/detail/meng_prautzsch_common.h>

namespace dlfl::detail {

/// center (a point, or the keyword "centroid"), random, epsilon, seed.
std::vector<ParamSpec> mp_shared_param_specs();

/// The centre of a resolved set: none for "centroid" (the scheme takes the vertex centroid).
std::optional<glm::dvec3> mp_center_from(const Params& resolved);

/// The random choices of a resolved set.
MpRandomChoice mp_random_from(const Params& resolved);

}  // namespace dlfl::detail

#pragma once
// Internal to the schemes: the `boundary` and `sharp_corners` parameters that every scheme taking open meshes
// declares, as data. Defined in boundary_params.cpp.

#include <vector>

#include <dlfl/parameters.h>
#include <dlfl/schemes/boundary_rule.h>

namespace dlfl::detail {

/// `boundary` (text: "curve", the default, or "hole"; a log of version 2 or older without it means "hole")
/// and `sharp_corners` (boolean, true).
std::vector<ParamSpec> boundary_param_specs();

/// `specs` followed by the boundary parameters.
std::vector<ParamSpec> with_boundary_params(std::vector<ParamSpec> specs);

/// The options of a resolved parameter set.
BoundaryOptions boundary_options_from(const Params& resolved);

}  // namespace dlfl::detail

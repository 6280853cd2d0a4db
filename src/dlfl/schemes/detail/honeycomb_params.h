#pragma once
// Internal to the schemes: the honeycomb's parameters as data, shared by honeycomb and dual-honeycomb-dual
// (which runs the honeycomb step on the dual). Defined in honeycomb.cpp.

#include <string>
#include <vector>

#include <dlfl/parameters.h>
#include <dlfl/schemes/honeycomb.h>

namespace dlfl::detail {

/// t, a, a0, a1 with their types, defaults and ranges (a0 and a1 have none of their own: a0 + a1/N must lie
/// in (0, 1) for the mesh's face sizes, which only the step can check), then `boundary` and `sharp_corners`
/// (detail/boundary_params.h).
std::vector<ParamSpec> honeycomb_param_specs();

/// `specs` followed by `planarize` (integer, 0 or 1, default 0: the lateral rule of
/// detail/honeycomb_planarize.h), which honeycomb and honeycomb-zw declare (dual-honeycomb-dual does not).
std::vector<ParamSpec> with_planarize_param(std::vector<ParamSpec> specs);

/// The check hook of both schemes: a constant `a` excludes a0/a1 (ParameterError naming `a`, in the words of
/// `scheme`), and when `a` is given the resolved set drops the a0/a1 defaults, so that a log records only
/// the tension in force.
void check_honeycomb_param_set(const std::string& scheme, const Params& given, Params& resolved);

/// The parameters of a resolved set as the scheme functions take them.
HoneycombParams honeycomb_params_from(const Params& resolved);

}  // namespace dlfl::detail

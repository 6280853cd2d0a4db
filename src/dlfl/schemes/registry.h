#pragma once
// Schemes by name, with their parameters as name -> value maps: what the tool and the operation log use.

#include <map>
#include <string>
#include <variant>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl {

/// A parameter value: a number, or text for structured values (a point "x,y,z", a pattern "H4P4").
using ParamValue = std::variant<double, std::string>;
/// Parameters by name.
using SchemeParams = std::map<std::string, ParamValue>;

/// Names accepted by `apply_scheme`, sorted.
std::vector<std::string> scheme_names();

/// The full parameter set for a scheme: the given values checked (names known, types right) and every default
/// filled in, so that logging the result records all the parameters. Throws InvalidArgument naming the scheme
/// or the parameter.
SchemeParams resolve_scheme_params(const std::string& scheme, const SchemeParams& given);

/// One step of the named scheme, with `params` as returned by `resolve_scheme_params` (or a subset of it).
/// The input is not modified. Throws InvalidArgument for an unknown scheme or a bad parameter.
Mesh apply_scheme(const Mesh& mesh, const std::string& scheme, const SchemeParams& params);

/// Parses "name=value" as given on a command line: a value that reads entirely as a number becomes a number,
/// anything else stays text. Throws InvalidArgument without '='.
std::pair<std::string, ParamValue> parse_param(const std::string& text);

}  // namespace dlfl

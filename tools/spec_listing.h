#pragma once
// Listings of declared parameters as text for people, shared by `dlfl ops` and `dlfl schemes` (their JSON
// comes from the library: dlfl/operations/spec_json.h).

#include <span>
#include <string>

#include <dlfl/parameters.h>

namespace dlfl::tool {

/// One line per parameter, in columns sized to `specs`: name, type, default, allowed values, doc, as in
/// "  t   number  default 0.5  in [0, 1]  where each edge's point lies ...". "  (no parameters)" for none.
std::string param_lines(std::span<const ParamSpec> specs);

}  // namespace dlfl::tool

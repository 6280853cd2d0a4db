#pragma once
// Listings of declared parameters, shared by `dlfl ops` and `dlfl schemes`: as text for people and as JSON
// for programs, in one format for both.

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include <dlfl/parameters.h>

namespace dlfl::tool {

/// {"name", "type", "default", "default_doc" (when set), "range": {"min", "max", "min_open", "max_open"}
/// (absent when unbounded), "keywords", "doc", "optional"}. "default" is typed (0.5, false, 1, "centroid",
/// [x, y, z]) or null when there is none; then "optional" says whether the parameter may be left out (and
/// "default_doc" how the value is chosen) or is required. An infinite end of a range is null and open (JSON
/// has no infinity).
nlohmann::ordered_json param_json(const ParamSpec& spec);

/// One line per parameter, in columns sized to `specs`: name, type, default, allowed values, doc, as in
/// "  t   number  default 0.5  in [0, 1]  where each edge's point lies ...". "  (no parameters)" for none.
std::string param_lines(std::span<const ParamSpec> specs);

}  // namespace dlfl::tool

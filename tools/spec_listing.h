#pragma once
// Listings of declared parameters, shared by `dlfl ops` and `dlfl schemes`: as text for people and as JSON
// for programs.

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include <dlfl/parameters.h>

namespace dlfl::tool {

/// {"name", "type", "doc", "default" (absent when required), "optional", "range" {"min", "max", "min_open",
/// "max_open"} (absent when unbounded), "keywords"}.
nlohmann::json param_json(const ParamSpec& spec);

/// One line per parameter: "  t  number = 0.5  in [0, 1]  the point (1 - t) v_m + t v_m+1 ...".
std::string param_lines(std::span<const ParamSpec> specs);

}  // namespace dlfl::tool

#include "scheme_options.h"

#include <dlfl/errors.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl::tool {

Params SchemeOptions::parsed_params() const {
  Params parsed;
  for (const auto& p : params) {
    auto [name, value] = parse_assignment(p);
    if (parsed.has(name)) throw ParameterError("parameter " + name + " given twice", name);
    parsed[name] = std::move(value);
  }
  return parsed;
}

std::pair<CLI::Option*, CLI::Option*> add_scheme_options(CLI::App* cmd, SchemeOptions& options,
                                                         bool required) {
  std::string names;
  for (const auto& n : scheme_names()) names += (names.empty() ? "" : ", ") + n;
  auto* scheme = cmd->add_option("-s,--scheme", options.scheme, "Scheme: " + names)->required(required);
  auto* iterations = cmd->add_option("-n,--iterations", options.iterations, "Number of steps (default 1)")
                         ->check(CLI::Range(0, 64));
  cmd->add_option("--param", options.params,
                  "Scheme parameter NAME=VALUE (repeatable), read as the parameter's type: t=0.5, "
                  "center=0,0,0, random=true, pattern=H4P4 ('dlfl schemes NAME' lists them)");
  return {scheme, iterations};
}

}  // namespace dlfl::tool

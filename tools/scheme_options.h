#pragma once
// The scheme options that `dlfl subdivide` and `dlfl view` share: -s SCHEME, -n ITERATIONS, --param
// NAME=VALUE.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include <dlfl/parameters.h>

namespace dlfl::tool {

/// A scheme, its number of steps and its parameters as given on the command line.
struct SchemeOptions {
  std::string scheme;
  int iterations = 1;
  std::vector<std::string> params;  // NAME=VALUE

  /// The parameters read by their types (not yet checked against the scheme). Throws ParameterError for a
  /// parameter given twice, UnknownNameError for a malformed assignment.
  Params parsed_params() const;
};

/// Declares -s,--scheme (required or not), -n,--iterations and --param on `cmd`; returns the -s and -n
/// options, for a command that needs to know whether they were given.
std::pair<CLI::Option*, CLI::Option*> add_scheme_options(CLI::App* cmd, SchemeOptions& options,
                                                         bool required);

}  // namespace dlfl::tool

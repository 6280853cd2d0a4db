#pragma once
// The subcommands of the dlfl tool. Each registers itself on the CLI11 app; its callback returns the exit
// code.

#include <CLI/CLI.hpp>
#include <functional>

namespace dlfl::tool {

/// Exit codes: 0 success, 1 failure (bad input, invalid mesh, I/O), 2 usage error.
enum Exit : int { ok = 0, failure = 1, usage = 2 };

/// A subcommand's action, run after parsing succeeded.
using Action = std::function<int()>;

Action add_info(CLI::App& app);
Action add_check(CLI::App& app);
Action add_convert(CLI::App& app);
Action add_subdivide(CLI::App& app);
Action add_replay(CLI::App& app);
Action add_ops(CLI::App& app);
Action add_edit(CLI::App& app);
Action add_schemes(CLI::App& app);
Action add_render(CLI::App& app);
Action add_view(CLI::App& app);

}  // namespace dlfl::tool

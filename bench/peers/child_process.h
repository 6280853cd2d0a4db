#pragma once
// Runs a program as a child process and measures it from outside: wall time, and the child's own rusage as
// wait4 reports it (CPU time, page faults, peak resident memory).

#include <string>
#include <utility>
#include <vector>

namespace dlfl::bench {

struct ChildRun {
  int exit_code = -1;  ///< the exit status, or -1 if the child was killed by a signal or could not start
  double wall = 0;     ///< seconds from fork to the end of wait4
  double user = 0;     ///< CPU seconds in user mode, all threads of the child
  double system = 0;   ///< CPU seconds in the kernel
  long minor_faults = 0;
  long major_faults = 0;
  double peak_rss_mib = 0;  ///< ru_maxrss
  std::string output;       ///< what the child wrote to stdout (stderr is passed through)
};

/// Runs `argv[0]` (a path) with `argv`, the environment of this process plus `env` (name, value), and waits
/// for it.
ChildRun run_child(const std::vector<std::string>& argv,
                   const std::vector<std::pair<std::string, std::string>>& env = {});

/// The folder of this program's executable, to find its sibling programs in the build's bin/ folder.
std::string own_folder();

}  // namespace dlfl::bench

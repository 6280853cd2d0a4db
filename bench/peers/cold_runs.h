#pragma once
// Cold runs: every timed step in a fresh dlfl_peer_step process, repeated, summed up by the run with the
// median step time.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "peer_schemes.h"
#include "step_measure.h"

namespace dlfl::bench {

/// What to run: a library, a scheme, the grid side, and a thread count for dlfl (0: the library's default).
struct Variant {
  std::string library;  ///< dlfl, cgal or openmesh
  Scheme scheme = Scheme::catmull_clark;
  std::size_t n = 0;
  unsigned threads = 0;
};

/// The run with the median step wall time, and the peak resident memory of that child (input included).
struct ColdResult {
  StepResult step;
  double peak_rss_mib = 0;
};

/// Runs each of `variants` in `runs` fresh processes of `helper` (the path of dlfl_peer_step), interleaved:
/// round r runs them all, starting with variant r (mod their number). The order matters on this VM: the step
/// right after a large process has ended can take several times as long, its extra time all in the kernel
/// (docs/performance.md), so each variant takes that place in at most one round in every few, and the median
/// leaves it out. `first_round` numbers the first round, so that successive calls go on turning (with one
/// run each, every variant still gets its turn at the front). Per variant the median run, or nothing if the
/// library has no such scheme. Throws std::runtime_error if a run fails.
std::vector<std::optional<ColdResult>> cold_runs(const std::string& helper,
                                                 const std::vector<Variant>& variants, int runs,
                                                 std::size_t first_round = 0);

}  // namespace dlfl::bench

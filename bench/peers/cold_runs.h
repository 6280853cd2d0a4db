#pragma once
// Cold runs: every timed step in a fresh dlfl_peer_step process, repeated, summed up by the run with the
// median step time.

#include <cstddef>
#include <optional>
#include <string>

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

/// Runs `variant` in `runs` fresh processes of `helper` (the path of dlfl_peer_step). Nothing if the library
/// has no such scheme; throws std::runtime_error if a run fails.
std::optional<ColdResult> cold_runs(const std::string& helper, const Variant& variant, int runs);

}  // namespace dlfl::bench

#pragma once
// What one timed step costs inside the process that runs it: wall time, and the CPU time and page faults that
// getrusage counts for the whole process (all its threads) between the step's start and end, so building the
// input is left out.

#include <sys/resource.h>
#include <chrono>
#include <cstddef>

namespace dlfl::bench {

struct StepCost {
  double wall = 0;    ///< seconds
  double user = 0;    ///< seconds of CPU in user mode, all threads
  double system = 0;  ///< seconds of CPU in the kernel, all threads
  long minor_faults = 0;
  long major_faults = 0;
};

inline double seconds(const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; }

/// Runs `step` once and returns its cost.
template <class F>
StepCost measure_step(F&& step) {
  rusage before{}, after{};
  getrusage(RUSAGE_SELF, &before);
  const auto start = std::chrono::steady_clock::now();
  step();
  const auto end = std::chrono::steady_clock::now();
  getrusage(RUSAGE_SELF, &after);
  return {std::chrono::duration<double>(end - start).count(),
          seconds(after.ru_utime) - seconds(before.ru_utime),
          seconds(after.ru_stime) - seconds(before.ru_stime), after.ru_minflt - before.ru_minflt,
          after.ru_majflt - before.ru_majflt};
}

/// The outcome of one step in a library: its cost and the face count of the result (the sanity check).
struct StepResult {
  StepCost cost;
  std::size_t input_faces = 0;
  std::size_t output_faces = 0;
};

}  // namespace dlfl::bench

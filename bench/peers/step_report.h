#pragma once
// The one line in which dlfl_peer_step hands its measurement to the benchmark that started it.

#include <cstdio>
#include <optional>
#include <string>

#include "step_measure.h"

namespace dlfl::bench {

/// The exit status of dlfl_peer_step when the library has no such scheme.
inline constexpr int scheme_unavailable = 3;

inline std::string format_report(const StepResult& r) {
  char line[256];
  std::snprintf(line, sizeof line, "step %zu %zu %.9f %.6f %.6f %ld %ld\n", r.input_faces, r.output_faces,
                r.cost.wall, r.cost.user, r.cost.system, r.cost.minor_faults, r.cost.major_faults);
  return line;
}

/// The report in a child's output; nothing if it holds none.
inline std::optional<StepResult> parse_report(const std::string& text) {
  const std::size_t at = text.rfind("step ");
  if (at == std::string::npos) return std::nullopt;
  StepResult r;
  if (std::sscanf(text.c_str() + at, "step %zu %zu %lf %lf %lf %ld %ld", &r.input_faces, &r.output_faces,
                  &r.cost.wall, &r.cost.user, &r.cost.system, &r.cost.minor_faults,
                  &r.cost.major_faults) != 7) {
    return std::nullopt;
  }
  return r;
}

}  // namespace dlfl::bench

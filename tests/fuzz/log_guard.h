#pragma once
// What the operation-log harness refuses to run, so that no input touches the file system or takes long:
// a `load` op that would read its `path` (one without an inline `mesh`), and logs that ask for more than
// `max_log_steps` subdivision steps in all (each step multiplies the mesh by up to 4).

#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>

namespace dlfl::fuzz {

inline constexpr std::size_t max_log_steps = 4;
/// Returned for anything the guard cannot bound: over any budget.
inline constexpr std::size_t unbounded = std::size_t(1) << 20;

/// The steps an MHP pattern expands to (1 for one that is refused: the scheme then fails at once).
inline std::size_t mhp_steps(const nlohmann::json& pattern) {
  if (!pattern.is_string()) return 1;
  try {
    return expand_mhp_pattern(pattern.get<std::string>()).size();
  } catch (const Error&) {
    return 1;
  }
}

/// The subdivision steps of one `subdivide` op of a log: iterations times the steps of each iteration.
/// Conservative: an iterations field that is not a plain number counts as unbounded.
inline std::size_t subdivision_steps(const nlohmann::json& op) {
  std::size_t iterations = 1;
  if (auto it = op.find("iterations"); it != op.end() && !it->is_null()) {
    if (!it->is_number()) return unbounded;
    const double d = it->get<double>();
    if (!(d >= 0) || d > 64) return 0;  // refused by the declared range [0, 64]: no work
    iterations = static_cast<std::size_t>(std::ceil(d));
  }
  std::size_t per_iteration = 1;
  auto scheme = op.find("scheme");
  auto params = op.find("params");
  if (scheme != op.end() && *scheme == "mhp" && params != op.end() && params->is_object()) {
    auto pattern = params->find("pattern");
    per_iteration = pattern == params->end() ? 2 : mhp_steps(*pattern);  // the default pattern is HP
  } else if (scheme != op.end() && *scheme == "mhp") {
    per_iteration = 2;
  }
  return iterations * per_iteration;
}

/// True if replaying `log` would read a file or run more than `max_log_steps` subdivision steps.
inline bool refuse_log(const nlohmann::json& log) {
  if (!log.is_object()) return false;
  auto ops = log.find("ops");
  if (ops == log.end() || !ops->is_array()) return false;
  std::size_t steps = 0;
  for (const auto& op : *ops) {
    if (!op.is_object()) continue;
    auto name = op.find("op");
    if (name == op.end()) continue;
    if (*name == "load") {
      auto mesh = op.find("mesh");
      if (mesh == op.end() || mesh->is_null()) return true;  // would read `path`
    }
    if (*name == "subdivide") steps += subdivision_steps(op);
    if (steps > max_log_steps) return true;
  }
  return false;
}

}  // namespace dlfl::fuzz

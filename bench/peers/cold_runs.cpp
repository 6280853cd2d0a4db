// Cold runs of several variants, interleaved (cold_runs.h).

#include "cold_runs.h"

#include <algorithm>
#include <stdexcept>

#include "child_process.h"
#include "step_report.h"

namespace dlfl::bench {

namespace {

// One fresh process; nothing if the library has no such scheme.
std::optional<ColdResult> cold_run(const std::string& helper, const Variant& variant) {
  std::vector<std::pair<std::string, std::string>> env;
  if (variant.threads > 0) env.emplace_back("DLFL_THREADS", std::to_string(variant.threads));
  const ChildRun child =
      run_child({helper, variant.library, scheme_name(variant.scheme), std::to_string(variant.n)}, env);
  if (child.exit_code == scheme_unavailable) return std::nullopt;
  const auto report = parse_report(child.output);
  if (child.exit_code != 0 || !report) {
    throw std::runtime_error(variant.library + " " + scheme_name(variant.scheme) +
                             " n=" + std::to_string(variant.n) + ": dlfl_peer_step failed (exit " +
                             std::to_string(child.exit_code) + ")");
  }
  return ColdResult{*report, child.peak_rss_mib};
}

}  // namespace

std::vector<std::optional<ColdResult>> cold_runs(const std::string& helper,
                                                 const std::vector<Variant>& variants, int runs,
                                                 std::size_t first_round) {
  const std::size_t count = variants.size();
  std::vector<std::vector<ColdResult>> results(count);
  std::vector<bool> available(count, true);
  for (int round = 0; round < runs; ++round) {
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = (first_round + std::size_t(round) + k) % count;
      if (!available[i]) continue;
      const auto result = cold_run(helper, variants[i]);
      if (result) {
        results[i].push_back(*result);
      } else {
        available[i] = false;
      }
    }
  }
  std::vector<std::optional<ColdResult>> medians(count);
  for (std::size_t i = 0; i < count; ++i) {
    auto& r = results[i];
    if (r.empty()) continue;
    std::sort(r.begin(), r.end(),
              [](const ColdResult& a, const ColdResult& b) { return a.step.cost.wall < b.step.cost.wall; });
    medians[i] = r[r.size() / 2];
  }
  return medians;
}

}  // namespace dlfl::bench

// Cold runs of one variant (cold_runs.h).

#include "cold_runs.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "child_process.h"
#include "step_report.h"

namespace dlfl::bench {

std::optional<ColdResult> cold_runs(const std::string& helper, const Variant& variant, int runs) {
  std::vector<std::pair<std::string, std::string>> env;
  if (variant.threads > 0) env.emplace_back("DLFL_THREADS", std::to_string(variant.threads));
  std::vector<ColdResult> results;
  for (int i = 0; i < runs; ++i) {
    const ChildRun child =
        run_child({helper, variant.library, scheme_name(variant.scheme), std::to_string(variant.n)}, env);
    if (child.exit_code == scheme_unavailable) return std::nullopt;
    const auto report = parse_report(child.output);
    if (child.exit_code != 0 || !report) {
      throw std::runtime_error(variant.library + " " + scheme_name(variant.scheme) +
                               " n=" + std::to_string(variant.n) + ": dlfl_peer_step failed (exit " +
                               std::to_string(child.exit_code) + ")");
    }
    results.push_back({*report, child.peak_rss_mib});
  }
  std::sort(results.begin(), results.end(),
            [](const ColdResult& a, const ColdResult& b) { return a.step.cost.wall < b.step.cost.wall; });
  return results[results.size() / 2];
}

}  // namespace dlfl::bench

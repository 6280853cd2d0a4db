#pragma once
// Timing helpers for the benchmark programs: median of repeated runs, and peak resident memory.

#include <sys/resource.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace dlfl::bench {

/// Wall times of repeated runs.
struct Timing {
  double median = 0;
  double best = 0;
};

/// Runs `f` `runs` times; median and best wall time in seconds. The best run is the one least disturbed by
/// the rest of the machine (on a shared VM, CPU steal can double a run).
inline Timing time_runs(int runs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return {t[t.size() / 2], t.front()};
}

/// Median wall time in seconds of `runs` runs.
inline double median_seconds(int runs, const std::function<void()>& f) { return time_runs(runs, f).median; }

/// CPU time stolen from this VM by its host so far, all cores, in seconds (0 where /proc/stat has no steal).
inline double steal_seconds() {
  FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return 0;
  unsigned long long v[8] = {};
  const int n = std::fscanf(f, "cpu %llu %llu %llu %llu %llu %llu %llu %llu", &v[0], &v[1], &v[2], &v[3],
                            &v[4], &v[5], &v[6], &v[7]);
  std::fclose(f);
  return n == 8 ? double(v[7]) / 100.0 : 0;  // USER_HZ ticks
}

/// /proc/loadavg's line ("1.02 0.87 0.75 2/345 6789\n"): how busy the shared machine is; empty if unknown.
inline std::string load_average() {
  char line[128] = {};
  FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f) return {};
  const bool read = std::fgets(line, sizeof line, f) != nullptr;
  std::fclose(f);
  return read ? line : "";
}

/// Peak resident set size of this process so far, in MiB.
inline double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

inline void row(const std::string& what, double seconds, const std::string& note = {}) {
  std::printf("%-34s %9.3f s   peak RSS %8.1f MiB  %s\n", what.c_str(), seconds, peak_rss_mib(),
              note.c_str());
  std::fflush(stdout);
}

}  // namespace dlfl::bench

#include <fstream>

namespace dlfl::bench {

/// A field of /proc/self/status in KiB (e.g. "VmRSS", "VmHWM"); 0 if unavailable.
inline long proc_status_kib(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string key;
  long value = 0;
  while (in >> key) {
    if (key == std::string(field) + ":") {
      in >> value;
      return value;
    }
    std::getline(in, key);
  }
  return 0;
}

/// Resets the peak-RSS mark (VmHWM) so the next phase's peak can be read on its own; false if not supported.
inline bool reset_peak_rss() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  return bool(out.flush());
}

}  // namespace dlfl::bench

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

/// Runs `f` `runs` times and returns the median wall time in seconds.
inline double median_seconds(int runs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
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

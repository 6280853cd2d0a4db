#pragma once
// What the tool tells its user while it works: with -v one summary line per step or file (counts and time)
// on stderr, and a progress bar on stderr when stderr is a terminal and a step or a file takes longer than
// about a second (DLFL_PROGRESS_AFTER seconds, default 1). --quiet silences both.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include <dlfl/mesh.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl::tool {

/// The feedback options, set once from the command line (main) before any command runs.
struct Feedback {
  bool verbose = false;
  bool quiet = false;
};
Feedback& feedback();

/// "V vertices, E edges, F faces" of a mesh.
std::string counts_text(const Mesh& mesh);

/// Prints one line on stderr when -v is on (and --quiet off).
void say(const std::string& line);

/// A progress line on stderr, redrawn by a thread of its own: the task, the fraction done when known, the
/// time so far. It shows only on a terminal, only after the delay, and never with --quiet; it clears itself.
class ProgressBar {
 public:
  ProgressBar();
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// What is being done now, and the fraction of the whole done so far (negative: unknown).
  void update(const std::string& task, double fraction);

 private:
  void run();
  void draw(bool clear);

  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::duration<double> delay_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  bool drawn_ = false;
  std::string task_;
  double fraction_ = -1;
  std::thread thread_;
};

/// Reports the scheme steps of a run of `iterations` steps (one or more subdivide ops): a -v line per step,
/// and a progress bar whose fraction weighs each step by its predicted size.
class StepReport : public StepObserver {
 public:
  /// `iterations` is the number of steps, 0 if unknown; `predicted_faces` the sum of the faces of all steps'
  /// results, 0 if unknown.
  StepReport(std::int64_t iterations, double predicted_faces);
  void step_started(std::string_view scheme, const Mesh& input) override;
  void step_finished(std::string_view scheme, const Mesh& output) override;

 private:
  std::string step_name(std::string_view scheme) const;
  std::int64_t iterations_;
  double predicted_faces_;
  double done_faces_ = 0;
  std::int64_t step_ = 0;
  std::chrono::steady_clock::time_point started_;
  ProgressBar bar_;
  ObservedSteps observing_;
};

/// Reports reading or writing one file: a progress bar while it lasts (after the delay) and, with -v, the
/// line "VERB FILE: counts in T s" when `done` is called.
class FileReport {
 public:
  FileReport(std::string verb, std::string file);
  /// The file is read or written; `mesh` is what it holds.
  void done(const Mesh& mesh);

 private:
  std::string verb_, file_;
  std::chrono::steady_clock::time_point started_;
  ProgressBar bar_;
};

/// Seconds as "0.012 s".
std::string seconds_text(double seconds);

}  // namespace dlfl::tool

#include "feedback.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace dlfl::tool {

Feedback& feedback() {
  static Feedback options;
  return options;
}

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f s", seconds);
  return text;
}

std::string counts_text(const Mesh& mesh) {
  return std::to_string(mesh.num_vertices()) + " vertices, " + std::to_string(mesh.num_edges()) + " edges, " +
         std::to_string(mesh.num_faces()) + " faces";
}

void say(const std::string& line) {
  if (feedback().verbose && !feedback().quiet) std::cerr << line << std::endl;
}

namespace {

double progress_delay() {
  const char* text = std::getenv("DLFL_PROGRESS_AFTER");
  if (!text) return 1.0;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  return end != text && seconds >= 0 ? seconds : 1.0;
}

constexpr int bar_width = 30;

// One bar at a time on the terminal line: a bar made while another is alive stays hidden.
std::atomic<int> bars_alive{0};

}  // namespace

ProgressBar::ProgressBar()
    : enabled_(bars_alive.fetch_add(1) == 0 && !feedback().quiet && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      delay_(progress_delay()) {
  if (enabled_) thread_ = std::thread([this] { run(); });
}

ProgressBar::~ProgressBar() {
  struct Leave {
    ~Leave() { bars_alive.fetch_sub(1); }
  } leave;
  if (!enabled_) return;
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ProgressBar::update(const std::string& task, double fraction) {
  std::lock_guard lock(mutex_);
  task_ = task;
  fraction_ = fraction;
  // Without a delay every update shows at once (and deterministically, which the tests rely on).
  if (enabled_ && delay_.count() == 0) draw(false);
}

void ProgressBar::run() {
  std::unique_lock lock(mutex_);
  if (wake_.wait_for(lock, delay_, [this] { return done_; })) return;  // finished before the delay: no bar
  while (!done_) {
    draw(false);
    wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return done_; });
  }
  draw(true);
}

// With the mutex held.
void ProgressBar::draw(bool clear) {
  if (clear) {
    if (drawn_) std::fprintf(stderr, "\r%*s\r", 79, "");
    std::fflush(stderr);
    return;
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
  // Appended piece by piece: gcc 12 warns (-Wrestrict, wrongly) on "literal" + string here.
  std::string line(1, '\r');
  line.append(task_).push_back(' ');
  if (fraction_ >= 0) {
    const double done = std::min(1.0, fraction_);
    const int filled = static_cast<int>(done * bar_width);
    line.push_back('[');
    line.append(static_cast<std::size_t>(filled), '#')
        .append(static_cast<std::size_t>(bar_width - filled), '.');
    line.append("] ").append(std::to_string(static_cast<int>(done * 100))).append("% ");
  }
  line += seconds_text(elapsed.count());
  if (line.size() < 80) line += std::string(80 - line.size(), ' ');
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
  drawn_ = true;
}

StepReport::StepReport(std::int64_t iterations, double predicted_faces)
    : iterations_(iterations), predicted_faces_(predicted_faces), observing_(*this) {}

std::string StepReport::step_name(std::string_view scheme) const {
  std::string name(scheme);
  name.append(" step ").append(std::to_string(step_));
  if (iterations_ > 0) name.append("/").append(std::to_string(iterations_));
  return name;
}

void StepReport::step_started(std::string_view scheme, const Mesh&) {
  ++step_;
  started_ = std::chrono::steady_clock::now();
  double fraction = -1;  // unknown
  if (predicted_faces_ > 0) {
    fraction = done_faces_ / predicted_faces_;
  } else if (iterations_ > 0) {
    fraction = static_cast<double>(step_ - 1) / static_cast<double>(iterations_);
  }
  bar_.update(step_name(scheme), fraction);
}

void StepReport::step_finished(std::string_view scheme, const Mesh& output) {
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - started_;
  done_faces_ += static_cast<double>(output.num_faces());
  say(step_name(scheme) + ": " + counts_text(output) + " in " + seconds_text(seconds.count()));
}

FileReport::FileReport(std::string verb, std::string file)
    : verb_(std::move(verb)), file_(std::move(file)), started_(std::chrono::steady_clock::now()) {
  bar_.update(verb_ + " " + file_, -1);
}

void FileReport::done(const Mesh& mesh) {
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - started_;
  say(verb_ + " " + file_ + ": " + counts_text(mesh) + " in " + seconds_text(seconds.count()));
}

}  // namespace dlfl::tool

// fork, exec and wait4 (child_process.h).

#include "child_process.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace dlfl::bench {

namespace {

double seconds(const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; }

}  // namespace

ChildRun run_child(const std::vector<std::string>& argv,
                   const std::vector<std::pair<std::string, std::string>>& env) {
  ChildRun run;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int out[2];
  if (pipe(out) != 0) return run;
  std::fflush(nullptr);  // nothing buffered may be written twice by the child
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return run;
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    close(out[1]);
    for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
    execv(args[0], args.data());
    std::perror(args[0]);
    _exit(127);
  }
  close(out[1]);
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(out[0], buffer, sizeof buffer);
    if (n > 0) run.output.append(buffer, std::size_t(n));
    if (n == 0 || (n < 0 && errno != EINTR)) break;
  }
  close(out[0]);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  run.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.user = seconds(usage.ru_utime);
  run.system = seconds(usage.ru_stime);
  run.minor_faults = usage.ru_minflt;
  run.major_faults = usage.ru_majflt;
  run.peak_rss_mib = double(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  return run;
}

std::string own_folder() { return std::filesystem::read_symlink("/proc/self/exe").parent_path().string(); }

}  // namespace dlfl::bench

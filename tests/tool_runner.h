#pragma once
// Runs the dlfl tool from a test: arguments in, exit code and captured stdout and stderr out, plus a scratch
// directory per test process. Only where the tool is built (DLFL_TOOL names its path).

#ifdef DLFL_TOOL
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace dlfl::test {

// CTest runs each test case as its own process, in parallel: every process gets its own directory, so
// no two of them share a captured stderr or an output file.
inline std::filesystem::path scratch_dir() {
  const auto dir = std::filesystem::temp_directory_path() / ("dlfl_tool_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

struct Run {
  int exit_code;
  std::string out;
  std::string err;
};

// Runs the tool with arguments (already shell-quoted where needed), capturing stdout and stderr.
inline Run run(const std::string& args) {
  const auto err_path = scratch_dir() / "stderr.txt";
  const std::string cmd = std::string("'") + DLFL_TOOL + "' " + args + " 2>'" + err_path.string() + "'";
  Run r{};
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(err_path);
  r.err.assign(std::istreambuf_iterator<char>(e), {});
  return r;
}

inline std::string example(const char* name) {
  return std::string("'") + DLFL_SOURCE_DIR + "/data/" + name + "'";
}

inline std::filesystem::path scratch(const char* name) {
  const auto dir = scratch_dir();
  std::filesystem::remove(dir / name);
  return dir / name;
}

}  // namespace dlfl::test
#endif

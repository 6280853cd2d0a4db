#pragma once
// Runs the dlfl tool from a test: arguments in, exit code and captured stdout and stderr out (in the
// process's scratch folder, test_helpers.h). Only where the tool is built (DLFL_TOOL names its path).

#ifdef DLFL_TOOL
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "test_helpers.h"

namespace dlfl::test {

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

}  // namespace dlfl::test
#endif

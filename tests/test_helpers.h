#pragma once
// Helpers shared by the tests: requiring a valid mesh (showing what is wrong when it is not), and scratch
// folders and files.

#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/validate.h>

namespace dlfl::test {

/// REQUIREs that `mesh` validates, first listing every violation found.
inline void require_valid(const Mesh& mesh) {
  const ValidationReport r = validate(mesh);
  if (!r.valid()) {
    for (const auto& v : r.violations) MESSAGE(to_string(v.code) << " " << v.element << ": " << v.message);
  }
  REQUIRE(r.valid());
}

/// The message of the exception of type E that a call throws (empty if it throws none).
template <class E, class F>
std::string error_message(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return {};
}

/// The scratch folder of this test process, created on first use and left for the next test case of the
/// process: CTest runs test cases as processes in parallel, and each gets its own folder.
inline std::filesystem::path scratch_dir() {
  const auto dir = std::filesystem::temp_directory_path() / ("dlfl_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// `name` in the process's scratch folder, with no file there yet.
inline std::filesystem::path scratch(const std::string& name) {
  const auto path = scratch_dir() / name;
  std::filesystem::remove(path);
  return path;
}

/// A fresh folder of its own under the system temp folder, removed with everything in it at the end of the
/// test: for checking which files a write leaves behind.
class ScratchDir {
 public:
  ScratchDir() {
    static std::mt19937_64 random{std::random_device{}()};
    path_ = std::filesystem::temp_directory_path() / ("dlfl_test_dir_" + std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  /// The names of everything in the folder, sorted: shows leftover output or temporary files.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

/// Writes `content` to `path` as it is (binary).
inline void write_text(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  REQUIRE(out.good());
}

/// `name` in the process's scratch folder, holding `content`: an input file for a test.
inline std::filesystem::path scratch_file(const std::string& name, const std::string& content) {
  const auto path = scratch(name);
  write_text(path, content);
  return path;
}

/// The whole content of `path` (empty if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace dlfl::test

#pragma once
// Helpers of the cell-complex file tests: a scratch folder, files from strings, exact comparison.

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <dlfl/cells/cell_complex.h>

namespace dlfl::test {

/// A fresh folder under the system temp folder, removed with everything in it at the end of the test.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir() {
    static std::mt19937_64 random{std::random_device{}()};
    path = std::filesystem::temp_directory_path() / ("dlfl_test_cells_" + std::to_string(random()));
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path / name; }
  /// Everything in the folder: shows leftover output or temporary files.
  std::size_t count() const {
    return std::size_t(
        std::distance(std::filesystem::directory_iterator(path), std::filesystem::directory_iterator()));
  }
};

inline void write_text(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  REQUIRE(out.good());
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Same cells in the same order and bit-identical positions.
inline void check_identical(const CellComplex& a, const CellComplex& b) {
  REQUIRE(a.positions.size() == b.positions.size());
  CHECK(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::dvec3)) == 0);
  CHECK(a.offsets == b.offsets);
  CHECK(a.indices == b.indices);
}

}  // namespace dlfl::test

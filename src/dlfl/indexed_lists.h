#pragma once
// Lists of vertex indices over a set of positions, stored flat: the storage that polygon soups (faces) and
// cell complexes (cells) share.

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace dlfl {

/// Positions plus lists of vertex indices, stored flat: list i uses `indices[offsets[i] .. offsets[i+1])`.
struct IndexedLists {
  std::vector<glm::dvec3> positions;
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;

 protected:
  std::size_t num_lists() const { return offsets.size() - 1; }
  std::span<const std::uint32_t> list(std::size_t i) const {
    return {indices.data() + offsets[i], indices.data() + offsets[i + 1]};
  }
  /// Appends a list (unchecked).
  void append_list(std::span<const std::uint32_t> list) {
    indices.insert(indices.end(), list.begin(), list.end());
    offsets.push_back(static_cast<std::uint32_t>(indices.size()));
  }
};

}  // namespace dlfl

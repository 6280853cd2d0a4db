#pragma once
// A plain indexed polygon list, the exchange form between files and the DLFL.

#include <cstdint>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <span>
#include <vector>

namespace dlfl {

/// Positions plus faces given as vertex indices (counter-clockwise seen from outside), stored flat: face i
/// uses `indices[offsets[i] .. offsets[i+1])`.
struct PolygonSoup {
  std::vector<glm::dvec3> positions;
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;

  std::size_t num_faces() const { return offsets.size() - 1; }
  std::span<const std::uint32_t> face(std::size_t i) const {
    return {indices.data() + offsets[i], indices.data() + offsets[i + 1]};
  }
  void add_face(std::span<const std::uint32_t> face) {
    indices.insert(indices.end(), face.begin(), face.end());
    offsets.push_back(static_cast<std::uint32_t>(indices.size()));
  }
  void add_face(std::initializer_list<std::uint32_t> face) { add_face(std::span(face.begin(), face.size())); }
};

}  // namespace dlfl

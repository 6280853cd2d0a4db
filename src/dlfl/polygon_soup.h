#pragma once
// A plain indexed polygon list, the exchange form between files and the DLFL.

#include <cstdint>
#include <initializer_list>
#include <span>

#include <dlfl/indexed_lists.h>

namespace dlfl {

/// Positions plus faces given as vertex indices (counter-clockwise seen from outside), stored flat: face i
/// uses `indices[offsets[i] .. offsets[i+1])`.
struct PolygonSoup : IndexedLists {
  std::size_t num_faces() const { return num_lists(); }
  std::span<const std::uint32_t> face(std::size_t i) const { return list(i); }
  void add_face(std::span<const std::uint32_t> face) { append_list(face); }
  void add_face(std::initializer_list<std::uint32_t> face) { add_face(std::span(face.begin(), face.size())); }
};

}  // namespace dlfl

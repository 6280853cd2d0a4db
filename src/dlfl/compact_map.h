#pragma once
// The old-to-new handle maps of `Mesh::compact()`, and how per-element values follow them.

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include <dlfl/handles.h>

namespace dlfl {

/// Old-to-new handle maps returned by `Mesh::compact` (invalid for removed elements), one entry per old slot.
struct CompactMap {
  std::vector<VertexId> vertices;
  std::vector<EdgeId> edges;
  std::vector<FaceId> faces;
  std::vector<CornerId> corners;

  /// The map of one element kind: `of<FaceId>()` is `faces`.
  template <class H>
  const std::vector<H>& of() const {
    if constexpr (std::is_same_v<H, VertexId>) {
      return vertices;
    } else if constexpr (std::is_same_v<H, EdgeId>) {
      return edges;
    } else if constexpr (std::is_same_v<H, FaceId>) {
      return faces;
    } else {
      return corners;
    }
  }
};

namespace detail {

/// Moves the values of live elements to their new slots and drops the rest. `values` may be shorter than the
/// map (the missing tail reads a default elsewhere): as compaction keeps the relative order, the live
/// elements among its slots land exactly on 0 .. k-1, and the result has k values. O(size).
template <class Values, class H>
void remap_slots(Values& values, const std::vector<H>& map) {
  const std::size_t n = std::min<std::size_t>(values.size(), map.size());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!map[i].valid()) continue;
    if (kept != i) values[kept] = std::move(values[i]);
    ++kept;
  }
  values.erase(values.begin() + static_cast<std::ptrdiff_t>(kept), values.end());
}

}  // namespace detail
}  // namespace dlfl

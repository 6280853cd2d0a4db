#pragma once
// A hash map of directed edges (a -> b) to a 32-bit value, bucketed by the source vertex: each vertex owns a
// small open-addressing table sized from its out-degree, all in one flat array. Lookups stay O(1) expected
// whatever the valence, and probes touch one or two cache lines near the vertex's neighbours, which is what
// makes building a million-face DLFL fast. Internal to the library.

#include <cstdint>
#include <span>
#include <vector>

#include <dlfl/detail/bucket_regions.h>
#include <dlfl/detail/large_allocator.h>

namespace dlfl::detail {

class EdgeMap {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;

  /// `out_degree[a]` bounds the number of keys (a, *) that will be inserted.
  explicit EdgeMap(std::span<const std::uint32_t> out_degree) : start_(out_degree.size() + 1) {
    slots_.assign(lay_out_regions(out_degree, start_), Slot{none, none});
  }

  /// Inserts (a,b) -> value unless (a,b) is present; returns the value stored for (a,b) afterwards.
  std::uint32_t insert(std::uint32_t a, std::uint32_t b, std::uint32_t value) {
    Slot* region = slots_.data() + start_[a];
    const std::size_t mask = start_[a + 1] - start_[a] - 1;
    for (std::size_t i = first_slot(b, mask);; i = (i + 1) & mask) {
      if (region[i].target == b) return region[i].value;
      if (region[i].target == none) {
        region[i] = {b, value};
        return value;
      }
    }
  }

  /// The value stored for (a,b), or `none`.
  std::uint32_t find(std::uint32_t a, std::uint32_t b) const {
    const std::size_t size = start_[a + 1] - start_[a];
    if (size == 0) return none;
    const Slot* region = slots_.data() + start_[a];
    const std::size_t mask = size - 1;
    for (std::size_t i = first_slot(b, mask);; i = (i + 1) & mask) {
      if (region[i].target == b) return region[i].value;
      if (region[i].target == none) return none;
    }
  }

 private:
  struct Slot {
    std::uint32_t target;
    std::uint32_t value;
  };
  // Large vectors: a million-face build's map is tens of megabytes, and blocks reused from the block cache
  // come back mapped instead of being faulted in page by page.
  LargeVector<std::size_t> start_;
  LargeVector<Slot> slots_;
};

}  // namespace dlfl::detail

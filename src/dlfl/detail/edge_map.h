#pragma once
// A hash map of directed edges (a -> b) to a 32-bit value, bucketed by the source vertex: each vertex owns a
// small open-addressing table sized from its out-degree, all in one flat array. Lookups stay O(1) expected
// whatever the valence, and probes touch one or two cache lines near the vertex's neighbours, which is what
// makes building a million-face DLFL fast. Internal to the library.

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

namespace dlfl::detail {

class EdgeMap {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;

  /// `out_degree[a]` bounds the number of keys (a, *) that will be inserted.
  explicit EdgeMap(std::span<const std::uint32_t> out_degree) : start_(out_degree.size() + 1) {
    std::size_t total = 0;
    for (std::size_t a = 0; a < out_degree.size(); ++a) {
      start_[a] = total;
      // Load factor at most one half; a power of two so the probe can wrap with a mask.
      total += out_degree[a] == 0 ? 0 : std::bit_ceil(2 * std::size_t(out_degree[a]));
    }
    start_.back() = total;
    slots_.assign(total, Slot{none, none});
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
  // Fibonacci hashing: the top log2(region size) bits of the product, the best-mixed ones, whatever the size
  // of the region (a vertex of degree 2^24 and more gets a region that a fixed shift would not cover).
  static std::size_t first_slot(std::uint32_t b, std::size_t mask) {
    const std::uint64_t h = std::uint64_t(b) * 0x9E3779B97F4A7C15ull;
    return mask == 0 ? 0 : static_cast<std::size_t>(h >> std::countl_zero(std::uint64_t(mask)));
  }

  std::vector<std::size_t> start_;
  std::vector<Slot> slots_;
};

}  // namespace dlfl::detail

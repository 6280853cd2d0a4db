#pragma once
// Internal: the layout the bucketed hash maps share (detail::EdgeMap, and VertexSetMap of the cells): each
// bucket (a vertex) owns a small open-addressing region of a power-of-two size, all regions in one flat
// array.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

namespace dlfl::detail {

/// Lays the regions out for buckets of at most `counts[a]` keys each: `start[a]` gets where bucket a's region
/// begins, `start[counts.size()]` (start holds one entry more than counts) the total, which is returned.
/// A region is a power of two, so a probe wraps with a mask, and at most half full even if every insertion
/// is a new key; an empty bucket gets none.
inline std::size_t lay_out_regions(std::span<const std::uint32_t> counts, std::span<std::size_t> start) {
  std::size_t total = 0;
  for (std::size_t a = 0; a < counts.size(); ++a) {
    start[a] = total;
    total += counts[a] == 0 ? 0 : std::bit_ceil(2 * std::size_t(counts[a]));
  }
  start[counts.size()] = total;
  return total;
}

/// The first slot to probe for hash `h` in a region of `mask + 1` slots. Fibonacci hashing: the top
/// log2(region size) bits of h times 2^64 / golden ratio, the best-mixed ones, whatever the size of the
/// region (one vertex may own tens of millions of keys; a fixed shift would not cover its region).
inline std::size_t first_slot(std::uint64_t h, std::size_t mask) {
  h *= 0x9E3779B97F4A7C15ull;
  return mask == 0 ? 0 : static_cast<std::size_t>(h >> std::countl_zero(std::uint64_t(mask)));
}

}  // namespace dlfl::detail

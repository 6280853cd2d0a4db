#pragma once
// A hash map from a set of K distinct vertex indices (given sorted) to a 32-bit value, bucketed by the
// smallest vertex: each vertex owns a small open-addressing table sized from the number of keys that can
// start with it, all in one flat array. This is how multi-linear subdivision shares the vertex it inserts on
// a coarse edge, face or cube among all the cells that contain that sub-face: O(1) expected per lookup at any
// valence, and cells that are close in the input probe memory that is close. Internal to the library.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <dlfl/detail/bucket_regions.h>
#include <dlfl/detail/large_allocator.h>

namespace dlfl::detail {

template <std::size_t K>
class VertexSetMap {
  static_assert(K >= 2, "a one-vertex set needs no map");

 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  using Key = std::array<std::uint32_t, K>;

  /// `starts_with[a]` bounds the number of insertions of keys whose smallest vertex is a.
  explicit VertexSetMap(std::span<const std::uint32_t> starts_with) : start_(starts_with.size() + 1) {
    const std::size_t total = lay_out_regions(starts_with, {start_.data(), start_.size()});
    Slot empty{};
    empty.rest.fill(none);
    empty.value = none;
    slots_.assign(total, empty);
  }

  /// Stores `value` for `key` (sorted ascending) unless the key is present; returns the value stored for it
  /// afterwards, so the caller learns whether its value was taken by comparing.
  std::uint32_t insert(const Key& key, std::uint32_t value) {
    Slot* region = slots_.data() + start_[key[0]];
    const std::size_t mask = start_[key[0] + 1] - start_[key[0]] - 1;
    for (std::size_t i = first_slot(key, mask);; i = (i + 1) & mask) {
      Slot& slot = region[i];
      if (slot.rest[0] == none) {
        for (std::size_t j = 1; j < K; ++j) slot.rest[j - 1] = key[j];
        slot.value = value;
        return value;
      }
      if (same_rest(slot, key)) return slot.value;
    }
  }

 private:
  struct Slot {
    std::array<std::uint32_t, K - 1> rest;  // the key without its smallest vertex; rest[0] == none: empty
    std::uint32_t value;
  };
  static bool same_rest(const Slot& slot, const Key& key) {
    for (std::size_t j = 1; j < K; ++j) {
      if (slot.rest[j - 1] != key[j]) return false;
    }
    return true;
  }
  // The rest of the key hashed as (((k1 C + k2) C + k3) C ...) C, the last multiplication first_slot's.
  static std::size_t first_slot(const Key& key, std::size_t mask) {
    std::uint64_t h = key[1];
    for (std::size_t j = 2; j < K; ++j) h = h * 0x9E3779B97F4A7C15ull + key[j];
    return detail::first_slot(h, mask);
  }

  LargeVector<std::size_t> start_;  // huge pages, and blocks reused from the previous step
  LargeVector<Slot> slots_;
};

}  // namespace dlfl::detail

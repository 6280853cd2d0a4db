#pragma once
// A flat open-addressing hash map from a directed vertex pair to a 32-bit value: the O(1) lookup behind
// building a DLFL from polygons. Internal to the library.

#include <cstdint>
#include <vector>

namespace dlfl::detail {

class EdgeMap {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;

  explicit EdgeMap(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < expected * 2) capacity *= 2;
    keys_.assign(capacity, empty_key);
    values_.resize(capacity);
    mask_ = capacity - 1;
  }

  /// Inserts (a,b) -> value unless (a,b) is present; returns the value stored for (a,b) afterwards.
  std::uint32_t insert(std::uint32_t a, std::uint32_t b, std::uint32_t value) {
    const std::uint64_t key = pack(a, b);
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return values_[i];
      if (keys_[i] == empty_key) {
        keys_[i] = key;
        values_[i] = value;
        return value;
      }
    }
  }

  /// The value stored for (a,b), or `none`.
  std::uint32_t find(std::uint32_t a, std::uint32_t b) const {
    const std::uint64_t key = pack(a, b);
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return values_[i];
      if (keys_[i] == empty_key) return none;
    }
  }

 private:
  static constexpr std::uint64_t empty_key = ~std::uint64_t(0);
  static std::uint64_t pack(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }
  std::size_t slot(std::uint64_t key) const {
    // Fibonacci hashing spreads the packed pairs; the high bits are the best mixed.
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask_;
  }

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t mask_ = 0;
};

}  // namespace dlfl::detail

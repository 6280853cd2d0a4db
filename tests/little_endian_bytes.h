#pragma once
// Little-endian bytes for hand-made binary files (PLY, STL), independent of the host's byte order.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

/// Appends `value` to `data` as its sizeof(T) little-endian bytes (floats and doubles as their IEEE bits).
template <class T>
void put_little_endian(std::string& data, T value) {
  std::uint64_t bits = 0;
  if constexpr (std::is_same_v<T, float>) {
    bits = std::bit_cast<std::uint32_t>(value);
  } else if constexpr (std::is_same_v<T, double>) {
    bits = std::bit_cast<std::uint64_t>(value);
  } else {
    bits = static_cast<std::make_unsigned_t<T>>(value);
  }
  for (std::size_t i = 0; i < sizeof(T); ++i) data.push_back(static_cast<char>((bits >> (8 * i)) & 0xFF));
}

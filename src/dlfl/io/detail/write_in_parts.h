#pragma once
// Internal: text output formatted on several threads, part by part, and written in order. Not part of the
// API.

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/detail/parallel_for.h>
#include <dlfl/io/detail/text_io.h>

namespace dlfl::io_detail {

/// Formats a part of a file into memory with BlockWriter's calls (numbers by std::to_chars, the same
/// characters). Its storage only grows, so that one writer serves many parts without new memory.
class TextWriter : public TextFormat<TextWriter> {
 public:
  void text(std::string_view s) {
    if (s.empty()) return;  // an empty view may have no data pointer, which memcpy must not get
    std::memcpy(room(s.size()), s.data(), s.size());
    size_ += s.size();
  }
  std::string_view view() const { return {text_.data(), size_}; }
  void clear() { size_ = 0; }

 private:
  friend class TextFormat<TextWriter>;
  char* room(std::size_t n) {
    if (text_.size() - size_ < n) text_.resize(std::max(2 * text_.size(), size_ + n + 4096));
    return text_.data() + size_;
  }
  void advance_to(const char* end) { size_ = static_cast<std::size_t>(end - text_.data()); }
  void advance_by_one() { ++size_; }
  std::string text_;
  std::size_t size_ = 0;
};

/// Lines (elements) per part: a few hundred kilobytes of text, enough that scheduling costs nothing beside
/// the formatting, little enough that the parts in flight stay small.
inline constexpr std::size_t lines_per_part = std::size_t{1} << 13;

/// Writes the lines of elements [0, count) to `w`: `format(writer, begin, end)` writes those of [begin, end)
/// with either writer (a generic lambda). Beyond one part, parts of `lines_per_part` are formatted in
/// parallel, a batch at a time, into the writers of `pool` (kept by the caller across calls, so that their
/// memory serves again), and written in order: the bytes are those of one serial call.
template <class Format>
void write_in_parts(BlockWriter& w, std::size_t count, std::vector<TextWriter>& pool, const Format& format) {
  if (count <= lines_per_part) {
    format(w, 0, count);
    return;
  }
  constexpr std::size_t batch = 16;
  const std::size_t total = detail::chunk_count(count, lines_per_part);
  if (pool.size() < std::min(batch, total)) pool.resize(std::min(batch, total));
  for (std::size_t first = 0; first < total; first += batch) {
    const std::size_t n = std::min(batch, total - first);
    detail::parallel_chunks(n, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) {
        pool[k].clear();
        const std::size_t begin = (first + k) * lines_per_part;
        format(pool[k], begin, std::min(count, begin + lines_per_part));
      }
    });
    for (std::size_t k = 0; k < n; ++k) w.text(pool[k].view());
  }
}

}  // namespace dlfl::io_detail

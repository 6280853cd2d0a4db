#pragma once
// Internal helpers shared by the mesh file readers and writers: reading a whole stream, a line scanner that
// parses numbers with std::from_chars, and a block writer that formats numbers with std::to_chars. Not part
// of the API.

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <glm/vec3.hpp>
#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include <dlfl/errors.h>
#include <dlfl/io/parsed_polygons.h>

namespace dlfl::io_detail {

/// Reads the rest of `in` into memory: parsing a buffer is far faster than extracting from a stream. A size
/// hint (the file size, if known) lets a file be read in one call. Throws IoError naming `name` on a read
/// error.
std::string read_all(std::istream& in, const std::string& name, std::size_t size_hint = 0);

/// Reads a whole file into memory. Throws IoError naming the path if it is a directory, cannot be opened or
/// fails to read.
std::string read_file(const std::filesystem::path& path);

/// The file's extension in lower case, with its dot (".obj"); empty if it has none.
std::string lower_extension(const std::filesystem::path& path);

/// The parsers proper, on a whole file in memory. The istream overloads (parse_obj of obj.h and so on,
/// defined in mesh_io.cpp) read the stream and call these.
ParsedPolygons parse_obj_text(std::string_view text, const std::string& name);
ParsedPolygons parse_off_text(std::string_view text, const std::string& name);
ParsedPolygons parse_ply_text(std::string_view text, const std::string& name);
/// STL's parser takes binary data as well as text (stl.h).
ParsedPolygons parse_stl_text(std::string_view data, const std::string& name);

/// Refuses text holding a byte that no text file has (NUL and the other C0 controls but \t \n \v \f \r, and
/// DEL; bytes from 0x80 up are allowed, as in UTF-8): IoError naming `name` and the byte's line (1-based).
void check_text(std::string_view text, const std::string& name);

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/// Largest index count a soup can hold: its offsets are 32-bit.
constexpr std::size_t max_indices = 0xFFFFFFFEu;

/// The polygon readers' messages for a face of `n` < 3 vertices, and for a vertex index `i` not below the
/// `num_vertices` the file declares.
std::string face_size_error(std::int64_t n);
std::string index_error(std::int64_t i, std::size_t num_vertices);

/// Closes the face whose indices were just appended to `parsed.soup`, read at line `line` (0 for a binary
/// file). The caller has checked the index count against `max_indices`.
inline void end_face(ParsedPolygons& parsed, std::size_t line) {
  parsed.soup.offsets.push_back(static_cast<std::uint32_t>(parsed.soup.indices.size()));
  parsed.face_lines.push_back(line);
}

/// Walks a text buffer line by line and reads blank-separated tokens and numbers within the current line.
/// Errors are IoErrors at the current line; after `next_line()` returned false that is the last line of the
/// text.
class LineScanner {
 public:
  /// With `hash_comments`, a token starting with '#' ends the line (OBJ, OFF). `lines_before` is the number
  /// of lines of the file before `text` when `text` is a part of it that starts at a line (a chunk parsed on
  /// its own), so that errors name the file's line.
  LineScanner(std::string_view text, const std::string& name, bool hash_comments,
              std::size_t lines_before = 0)
      : next_(text.data()),
        end_(text.data() + text.size()),
        begin_(text.data()),
        name_(name),
        line_(lines_before),
        comments_(hash_comments) {
    // A UTF-8 byte order mark, at the start of the file only.
    if (lines_before == 0 && text.starts_with("\xEF\xBB\xBF")) next_ += 3;
    p_ = eol_ = next_;
  }

  /// Moves to the next line; false at the end of the text.
  bool next_line() {
    if (next_ == end_) return false;
    p_ = next_;
    const auto* nl = static_cast<const char*>(std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_)));
    eol_ = nl ? nl : end_;
    next_ = nl ? nl + 1 : end_;
    ++line_;
    return true;
  }
  std::size_t line() const { return line_; }
  /// Offset in the text where the next line starts (for binary data after a text header).
  std::size_t next_offset() const { return static_cast<std::size_t>(next_ - begin_); }
  /// Bytes not yet consumed, from the current position: a bound on how many more elements the text can hold.
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

  /// Skips blanks; true if nothing but a comment is left on the line.
  bool at_eol() {
    while (p_ != eol_ && is_blank(*p_)) ++p_;
    return p_ == eol_ || (comments_ && *p_ == '#');
  }
  /// The next token on the line, or empty at the end of the line.
  std::string_view token() {
    if (at_eol()) return {};
    const char* start = p_;
    while (p_ != eol_ && !is_blank(*p_)) ++p_;
    return {start, static_cast<std::size_t>(p_ - start)};
  }
  /// The rest of the line without leading or trailing blanks (for messages).
  std::string_view rest() {
    at_eol();
    const char* e = eol_;
    while (e != p_ && is_blank(e[-1])) --e;
    return {p_, static_cast<std::size_t>(e - p_)};
  }

  /// Reads three finite numbers, the x, y and z coordinates of a point.
  glm::dvec3 point() {
    glm::dvec3 p;
    p.x = number("x coordinate");
    p.y = number("y coordinate");
    p.z = number("z coordinate");
    return p;
  }

  /// Reads a finite floating-point number; `what` names it in errors ("x coordinate").
  double number(const char* what) {
    if (at_eol()) fail(std::string("missing ") + what);
    const char* b = skip_plus();
    double value = 0;
    auto [ptr, ec] = std::from_chars(b, eol_, value);
    if (ec == std::errc::result_out_of_range) {
      // from_chars reports both overflow and underflow; a tiny number such as 1e-400 reads as zero.
      if (!ends_token(ptr) || !is_underflow(b, ptr))
        fail(std::string(what) + " '" + word() + "' is out of range");
      value = *b == '-' ? -0.0 : 0.0;
    } else if (ec != std::errc() || !ends_token(ptr)) {
      fail(std::string("bad ") + what + " '" + word() + "'");
    }
    if (!std::isfinite(value)) fail(std::string(what) + " '" + word() + "' is not finite");
    p_ = ptr;
    return value;
  }

  /// Reads an integer. With `suffix`, the token may go on after the number with that character (OBJ's
  /// "7/2/5"), and the rest of the token is skipped.
  std::int64_t integer(const char* what, char suffix = 0) {
    if (at_eol()) fail(std::string("missing ") + what);
    const char* b = skip_plus();
    // The common case, a few plain digits ending the token (or followed by the suffix), without from_chars;
    // anything else takes the general path below.
    std::uint64_t digits = 0;
    const char* q = b;
    for (; q != eol_ && q - b < 18 && unsigned(*q - '0') < 10; ++q) digits = digits * 10 + unsigned(*q - '0');
    if (q != b && (q == eol_ || unsigned(*q - '0') >= 10)) {
      if (suffix != 0 && q != eol_ && *q == suffix) {
        while (q != eol_ && !is_blank(*q)) ++q;
        p_ = q;
        return static_cast<std::int64_t>(digits);
      }
      if (ends_token(q)) {
        p_ = q;
        return static_cast<std::int64_t>(digits);
      }
    }
    std::int64_t value = 0;
    auto [ptr, ec] = std::from_chars(b, eol_, value);
    if (ec == std::errc::result_out_of_range) fail(std::string(what) + " '" + word() + "' is out of range");
    if (ec != std::errc()) fail(std::string("bad ") + what + " '" + word() + "'");
    if (suffix != 0 && ptr != eol_ && *ptr == suffix) {
      while (ptr != eol_ && !is_blank(*ptr)) ++ptr;
    } else if (!ends_token(ptr)) {
      fail(std::string("bad ") + what + " '" + word() + "'");
    }
    p_ = ptr;
    return value;
  }

  [[noreturn]] void fail(const std::string& message) const { throw IoError(message, name_, line_); }

 private:
  // from_chars rejects a leading '+', which some writers emit.
  const char* skip_plus() const {
    return (*p_ == '+' && p_ + 1 != eol_ && p_[1] != '-' && p_[1] != '+') ? p_ + 1 : p_;
  }
  bool ends_token(const char* ptr) const {
    return ptr == eol_ || is_blank(*ptr) || (comments_ && *ptr == '#');
  }
  static bool is_underflow(const char* b, const char* e) {
    const char* x = std::find_if(b, e, [](char c) { return c == 'e' || c == 'E'; });
    return x + 1 < e && x[1] == '-';
  }
  // The current token, for messages.
  std::string word() const {
    const char* e = p_;
    while (e != eol_ && !is_blank(*e)) ++e;
    return std::string(p_, e);
  }

  const char* p_;     // position in the current line
  const char* eol_;   // end of the current line (its '\n' or the end of the text)
  const char* next_;  // start of the next line
  const char* end_;
  const char* begin_;
  const std::string& name_;
  std::size_t line_;
  bool comments_;
};

/// Reads one OBJ vertex reference (`i`, `i/t`, `i/t/n`) and returns its 0-based index. A negative `i` counts
/// back from the `defined` vertices read so far; a positive one is checked against the vertex count by the
/// caller, after the whole file (a statement may name a vertex defined further down). IoError at the current
/// line for 0 or an index out of range.
inline std::uint32_t obj_vertex_index(LineScanner& s, std::int64_t defined) {
  const std::int64_t i = s.integer("vertex index", '/');
  if (i > 0) {
    if (i - 1 >= static_cast<std::int64_t>(max_indices)) {
      s.fail("vertex index " + std::to_string(i) + " is out of range");
    }
    return static_cast<std::uint32_t>(i - 1);
  }
  if (i < 0) {
    if (defined + i < 0) {
      s.fail("relative vertex index " + std::to_string(i) + " is out of range (" + std::to_string(defined) +
             " vertices so far)");
    }
    return static_cast<std::uint32_t>(defined + i);
  }
  s.fail("vertex index 0 is out of range (OBJ indices start at 1)");
}

/// The check that `obj_vertex_index` leaves to the end of the file: every index of the `count` lists
/// (`list(i)` for list i, read at line `lines[i]`) is below `num_vertices`. Throws IoError naming `name`, the
/// line and the index as the file writes it (1-based).
template <class List>
void check_obj_indices(std::size_t count, const List& list, std::span<const std::size_t> lines,
                       std::size_t num_vertices, const std::string& name) {
  for (std::size_t i = 0; i < count; ++i) {
    for (std::uint32_t v : list(i)) {
      if (v >= num_vertices) {
        throw IoError("vertex index " + std::to_string(std::uint64_t{v} + 1) +
                          " is out of range (there are " + std::to_string(num_vertices) + " vertices)",
                      name, lines[i]);
      }
    }
  }
}

/// Converts between the host's byte order and `order` (a no-op when they agree).
template <std::endian order, class T>
T with_byte_order(T value) {
  if constexpr (std::endian::native != order) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    std::reverse(bytes, bytes + sizeof(T));
    std::memcpy(&value, bytes, sizeof(T));
  }
  return value;
}

/// Converts between the host's byte order and little-endian (PLY binary).
template <class T>
T little_endian(T value) {
  return with_byte_order<std::endian::little>(value);
}

/// Converts between the host's byte order and big-endian (VTK legacy binary).
template <class T>
T big_endian(T value) {
  return with_byte_order<std::endian::big>(value);
}

/// The number and line formats that every text writer shares (numbers by std::to_chars, shortest round-trip
/// for doubles), written through the writer's `room(n)` (space for n more characters, returned as a pointer)
/// and `advance_to(end)` (the text now ends at `end`), which it lets this base call.
template <class Writer>
class TextFormat {
 public:
  void put(char c) {
    *self().room(1) = c;
    self().advance_by_one();
  }
  void number(double value) { format(value, 32); }  // the longest shortest-form double is 24 characters
  /// A float in its shortest round-trip form (STL text, which so holds the values that binary STL holds).
  void number(float value) { format(value, 24); }  // the longest shortest-form float is 15 characters
  void number(std::uint64_t value) { format(value, 24); }
  /// "x y z\n", shortest round-trip decimals.
  void point_line(const glm::dvec3& p) {
    number(p.x);
    put(' ');
    number(p.y);
    put(' ');
    number(p.z);
    put('\n');
  }
  /// "n i0 i1 ...\n": a face as OFF and ASCII PLY write it.
  void counted_face_line(std::span<const std::uint32_t> face) {
    number(std::uint64_t{face.size()});
    for (std::uint32_t i : face) {
      put(' ');
      number(std::uint64_t{i});
    }
    put('\n');
  }

 private:
  Writer& self() { return static_cast<Writer&>(*this); }
  template <class T>
  void format(T value, std::size_t most) {
    char* p = self().room(most);
    self().advance_to(std::to_chars(p, p + most, value).ptr);
  }
};

/// Collects output in a large buffer and hands it to the stream in big blocks; numbers are formatted with
/// std::to_chars (shortest round-trip for doubles). Call `flush()` at the end; stream errors are left in the
/// stream's state for the caller to check.
class BlockWriter : public TextFormat<BlockWriter> {
 public:
  explicit BlockWriter(std::ostream& out) : out_(out), buffer_(new char[capacity]) {}
  BlockWriter(const BlockWriter&) = delete;
  BlockWriter& operator=(const BlockWriter&) = delete;

  void text(std::string_view s);
  /// The bytes of `value` in little-endian order.
  template <class T>
  void binary(T value) {
    value = little_endian(value);
    std::memcpy(room(sizeof(T)), &value, sizeof(T));
    size_ += sizeof(T);
  }
  /// The bytes of each value in little-endian order: one copy on a little-endian host.
  void binary_values(std::span<const std::uint32_t> values) {
    const std::size_t bytes = values.size() * sizeof(std::uint32_t);
    if (std::endian::native == std::endian::little && bytes <= capacity) {
      std::memcpy(room(bytes), values.data(), bytes);
      size_ += bytes;
      return;
    }
    for (std::uint32_t v : values) binary(v);
  }
  void flush();

 private:
  friend class TextFormat<BlockWriter>;
  static constexpr std::size_t capacity = std::size_t{1} << 20;
  char* room(std::size_t n) {
    if (capacity - size_ < n) flush();
    return buffer_.get() + size_;
  }
  void advance_to(const char* end) { size_ = static_cast<std::size_t>(end - buffer_.get()); }
  void advance_by_one() { ++size_; }

  std::ostream& out_;
  std::unique_ptr<char[]> buffer_;
  std::size_t size_ = 0;
};

}  // namespace dlfl::io_detail

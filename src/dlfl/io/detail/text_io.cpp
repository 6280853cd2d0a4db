#include <dlfl/io/detail/text_io.h>

#include <cctype>
#include <cerrno>
#include <fstream>
#include <istream>
#include <ostream>
#include <system_error>

namespace dlfl::io_detail {

std::string read_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw IoError("cannot open: it is a directory", name);
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if (!in) throw IoError("cannot open: " + std::generic_category().message(errno), name);
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return read_all(in, name, ec ? 0 : static_cast<std::size_t>(size));
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string read_all(std::istream& in, const std::string& name, std::size_t size_hint) {
  if (size_hint == 0) {
    // A seekable stream (a file, a string stream) tells how much is left, so that one read suffices.
    std::streambuf* buffer = in.rdbuf();
    const auto here = buffer ? buffer->pubseekoff(0, std::ios::cur, std::ios::in) : std::streampos(-1);
    if (here != std::streampos(-1)) {
      const auto end = buffer->pubseekoff(0, std::ios::end, std::ios::in);
      buffer->pubseekpos(here, std::ios::in);
      if (end != std::streampos(-1) && end > here) size_hint = static_cast<std::size_t>(end - here);
    }
  }
  std::string data;
  std::size_t size = 0;
  // One byte more than the hint so that a file of exactly that size hits the end in the first read.
  std::size_t chunk = std::max<std::size_t>(size_hint + 1, std::size_t{1} << 16);
  while (in) {
    data.resize(size + chunk);
    in.read(data.data() + size, static_cast<std::streamsize>(chunk));
    size += static_cast<std::size_t>(in.gcount());
    chunk = std::max(chunk, size);  // grow geometrically when the size is not known
  }
  if (in.bad() || !in.eof()) throw IoError("read error", name);
  data.resize(size);
  return data;
}

void BlockWriter::text(std::string_view s) {
  if (s.empty()) return;  // an empty view may have no data pointer, which memcpy must not get
  // A large piece goes to the stream as it is, rather than through the buffer.
  const bool large = s.size() >= capacity / 4;
  if (large || s.size() > capacity - size_) {
    flush();
    if (large) {
      out_.write(s.data(), static_cast<std::streamsize>(s.size()));
      return;
    }
  }
  std::memcpy(buffer_.get() + size_, s.data(), s.size());
  size_ += s.size();
}

void BlockWriter::flush() {
  if (size_ != 0) out_.write(buffer_.get(), static_cast<std::streamsize>(size_));
  size_ = 0;
}

namespace {
// A byte that no text file holds: NUL and the other C0 controls but \t \n \v \f \r, and DEL. Bytes from
// 0x80 up are allowed (UTF-8 in comments and names).
constexpr bool is_binary_byte(unsigned char c) { return c < 9 || (c >= 14 && c < 32) || c == 127; }

}  // namespace

// Scanned in blocks with a branch-free test that the compiler vectorises, so that checking a large file costs
// a few milliseconds, not a second parse.
void check_text(std::string_view text, const std::string& name) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  constexpr std::size_t block = 4096;
  for (std::size_t begin = 0; begin < text.size(); begin += block) {
    const std::size_t end = std::min(text.size(), begin + block);
    std::uint8_t found = 0;  // bytes throughout, so that the loop runs 16 or 32 bytes a step
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint8_t c = bytes[i];
      found |= std::uint8_t(c < 9) | std::uint8_t(std::uint8_t(c - 14) < 18) | std::uint8_t(c == 127);
    }
    if (found == 0) continue;
    std::size_t at = begin;
    while (!is_binary_byte(bytes[at])) ++at;
    const auto line = static_cast<std::size_t>(
                          std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) +
                      1;
    throw IoError("binary data at line " + std::to_string(line) + " (byte " +
                      std::to_string(unsigned(bytes[at])) + "): not a text file",
                  name, line);
  }
}

std::string face_size_error(std::int64_t n) {
  return "face has " + std::to_string(n) + " vertices; at least 3 are needed";
}

std::string index_error(std::int64_t i, std::size_t num_vertices) {
  return "vertex index " + std::to_string(i) + " is out of range (there are " + std::to_string(num_vertices) +
         " vertices)";
}

}  // namespace dlfl::io_detail

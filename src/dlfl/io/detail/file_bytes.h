#pragma once
// Internal: a whole file in memory, read-only, mapped rather than copied where the system allows. Not part of
// the API.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace dlfl::io_detail {

/// The bytes of a file. A regular file of a megabyte or more is mapped into memory (POSIX mmap), which
/// spares copying it and clearing a buffer for it; any other file (small, a pipe, or where mapping fails) is
/// read from the same descriptor into memory (elsewhere than POSIX: read_file). Like any mapping, a mapped
/// file must not be truncated by another process while it is read.
class FileBytes {
 public:
  /// Throws IoError naming the path as read_file does: a directory, a file that cannot be opened or read.
  explicit FileBytes(const std::filesystem::path& path);
  ~FileBytes();
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  std::string_view view() const { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
  bool mapped_ = false;
  std::string copy_;  // the bytes when not mapped
};

}  // namespace dlfl::io_detail

#include <dlfl/io/detail/file_bytes.h>

#include <cerrno>
#include <system_error>

#include <dlfl/errors.h>
#include <dlfl/io/detail/text_io.h>

#if !defined(_WIN32)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace dlfl::io_detail {

namespace {

// Below this a read costs as little as a mapping.
constexpr std::size_t min_mapped_bytes = std::size_t{1} << 20;

}  // namespace

FileBytes::FileBytes(const std::filesystem::path& path) {
#if !defined(_WIN32)
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw IoError("cannot open: it is a directory", path.string());
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw IoError("cannot open: " + std::generic_category().message(errno), path.string());
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && std::size_t(st.st_size) >= min_mapped_bytes) {
    const auto size = static_cast<std::size_t>(st.st_size);
    // Populated at once: the parser reads every page, and faulting them in one by one costs more.
    void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (map != MAP_FAILED) {
      ::madvise(map, size, MADV_SEQUENTIAL);
      data_ = static_cast<const char*>(map);
      size_ = size;
      mapped_ = true;
    }
  }
  ::close(fd);
  if (mapped_) return;
#endif
  copy_ = read_file(path);
  data_ = copy_.data();
  size_ = copy_.size();
}

FileBytes::~FileBytes() {
#if !defined(_WIN32)
  if (mapped_) ::munmap(const_cast<char*>(data_), size_);
#endif
}

}  // namespace dlfl::io_detail

#include <dlfl/io/detail/file_bytes.h>

#include <algorithm>
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
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw IoError("cannot open: it is a directory", name);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw IoError("cannot open: " + std::generic_category().message(errno), name);
  struct stat st {};
  const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  if (regular && std::size_t(st.st_size) >= min_mapped_bytes) {
    const auto size = static_cast<std::size_t>(st.st_size);
    // Populated at once: the parser reads every page, and faulting them in one by one costs more.
    void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (map != MAP_FAILED) {
      ::madvise(map, size, MADV_SEQUENTIAL);
      data_ = static_cast<const char*>(map);
      size_ = size;
      mapped_ = true;
      ::close(fd);
      return;
    }
  }
  // Read from this very descriptor: a named pipe opened twice would wait for a second writer.
  std::size_t size = 0;
  std::size_t chunk = std::max<std::size_t>(regular ? std::size_t(st.st_size) + 1 : 0, std::size_t{1} << 16);
  for (;;) {
    copy_.resize(size + chunk);
    const ::ssize_t got = ::read(fd, copy_.data() + size, chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      ::close(fd);
      throw IoError("read error", name);
    }
    if (got == 0) break;
    size += static_cast<std::size_t>(got);
    chunk = std::max(chunk, size);  // grow geometrically when the size is not known
  }
  ::close(fd);
  copy_.resize(size);
#else
  copy_ = read_file(path);
#endif
  data_ = copy_.data();
  size_ = copy_.size();
}

FileBytes::~FileBytes() {
#if !defined(_WIN32)
  if (mapped_) ::munmap(const_cast<char*>(data_), size_);
#endif
}

}  // namespace dlfl::io_detail

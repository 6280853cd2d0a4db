#include <dlfl/io/atomic_file.h>

#include <atomic>
#include <cerrno>
#include <fstream>
#include <string>
#include <system_error>

#include <dlfl/errors.h>

#if defined(_WIN32)
#include <process.h>
#define DLFL_GETPID _getpid
#else
#include <unistd.h>
#define DLFL_GETPID getpid
#endif

namespace dlfl {

namespace {
// The process id keeps concurrent processes apart, the counter concurrent writes within one process.
std::filesystem::path temporary_path(const std::filesystem::path& path) {
  static std::atomic<unsigned long> counter{0};
  std::filesystem::path temp = path;
  temp += ".tmp-" + std::to_string(static_cast<long>(DLFL_GETPID())) + "-" + std::to_string(counter++);
  return temp;
}
}  // namespace

void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                      bool binary) {
  const std::filesystem::path temp = temporary_path(path);
  std::ofstream out(
      temp, binary ? std::ios::out | std::ios::trunc | std::ios::binary : std::ios::out | std::ios::trunc);
  if (!out) {
    const std::string reason = std::generic_category().message(errno);
    throw IoError("cannot create the temporary file " + temp.string() + ": " + reason, path.string());
  }
  try {
    write(out);
    out.flush();
    if (!out) throw IoError("writing the temporary file " + temp.string() + " failed", path.string());
    out.close();
    if (!out) throw IoError("closing the temporary file " + temp.string() + " failed", path.string());
    // rename replaces the target in one step, so readers see either the old or the new file, never a mix.
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) throw IoError("cannot move " + temp.string() + " into place: " + ec.message(), path.string());
  } catch (...) {
    if (out.is_open()) out.close();
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

}  // namespace dlfl

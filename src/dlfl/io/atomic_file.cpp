#include <dlfl/io/atomic_file.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include <dlfl/errors.h>

#if defined(_WIN32)
#include <io.h>
#include <process.h>
#define DLFL_GETPID _getpid
#define DLFL_UNLINK _unlink
#else
#include <unistd.h>
#define DLFL_GETPID getpid
#define DLFL_UNLINK unlink
#endif

namespace fs = std::filesystem;

namespace dlfl {

namespace {

// The process id keeps concurrent processes apart, the counter concurrent writes within one process.
fs::path temporary_path(const fs::path& path) {
  static std::atomic<unsigned long> counter{0};
  fs::path temp = path;
  temp += ".tmp-" + std::to_string(static_cast<long>(DLFL_GETPID())) + "-" + std::to_string(counter++);
  return temp;
}

// The names of the live temporary files, where a signal handler can read them: fixed buffers (a handler may
// not allocate or lock) claimed through an atomic flag. A file whose name does not fit, or that finds every
// slot taken, is still removed by its batch, just not by a signal.
constexpr int slot_count = 64;
constexpr std::size_t slot_bytes = 1024;
std::array<std::atomic<bool>, slot_count> slot_used{};
char slot_names[slot_count][slot_bytes];
std::atomic_flag slot_claiming = ATOMIC_FLAG_INIT;

int claim_slot(const fs::path& temp) {
  const std::string name = temp.string();
  if (name.size() >= slot_bytes) return -1;
  while (slot_claiming.test_and_set(std::memory_order_acquire)) {
  }
  int slot = -1;
  for (int i = 0; i < slot_count && slot < 0; ++i) {
    if (slot_used[i].load(std::memory_order_relaxed)) continue;
    std::memcpy(slot_names[i], name.c_str(), name.size() + 1);
    slot_used[i].store(true, std::memory_order_release);
    slot = i;
  }
  slot_claiming.clear(std::memory_order_release);
  return slot;
}

void release_slot(int slot) {
  if (slot >= 0) slot_used[slot].store(false, std::memory_order_release);
}

void remove_quietly(const fs::path& p) {
  std::error_code ignored;
  fs::remove(p, ignored);
}

std::string errno_text() { return std::generic_category().message(errno); }

}  // namespace

fs::path write_target(const fs::path& path) {
  fs::path p = path;
  // 40 links, as the kernel allows before ELOOP; a longer chain is written as it stands and fails there.
  for (int i = 0; i < 40; ++i) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) break;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) break;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return p;
}

void check_writable(const fs::path& path) {
  const fs::path final = write_target(path);
  const fs::path folder = final.parent_path().empty() ? fs::path(".") : final.parent_path();
  std::error_code ec;
  const fs::file_status folder_status = fs::status(folder, ec);
  if (!fs::exists(folder_status))
    throw IoError("its folder " + folder.string() + " does not exist", path.string());
  if (!fs::is_directory(folder_status)) throw IoError(folder.string() + " is not a folder", path.string());
#if !defined(_WIN32)
  if (access(folder.c_str(), W_OK) != 0)
    throw IoError("cannot write in its folder " + folder.string() + ": " + errno_text(), path.string());
#endif
  const fs::file_status status = fs::status(final, ec);
  if (!fs::exists(status)) return;
  if (fs::is_directory(status)) throw IoError("is a folder", path.string());
  if (!fs::is_regular_file(status)) throw IoError("is not a regular file", path.string());
  constexpr fs::perms write_bits = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
  if ((status.permissions() & write_bits) == fs::perms::none)
    throw IoError("is read-only; make it writable or choose another output", path.string());
}

FileBatch::~FileBatch() { discard(); }

void FileBatch::discard() {
  for (const Staged& s : staged_) {
    remove_quietly(s.temporary);
    release_slot(s.slot);
  }
  staged_.clear();
}

void FileBatch::stage(const fs::path& path, const std::function<void(std::ostream&)>& write, bool binary) {
  check_writable(path);
  Staged s{path, write_target(path), {}, -1};
  s.temporary = temporary_path(s.final);
  s.slot = claim_slot(s.temporary);
  std::ofstream out(s.temporary, binary ? std::ios::out | std::ios::trunc | std::ios::binary
                                        : std::ios::out | std::ios::trunc);
  try {
    if (!out)
      throw IoError("cannot create the temporary file " + s.temporary.string() + ": " + errno_text(),
                    path.string());
    write(out);
    out.flush();
    if (!out) throw IoError("writing the temporary file " + s.temporary.string() + " failed", path.string());
    out.close();
    if (!out) throw IoError("closing the temporary file " + s.temporary.string() + " failed", path.string());
    // The new file takes the permission bits of the one it replaces.
    std::error_code missing;
    const fs::file_status old = fs::status(s.final, missing);
    if (fs::exists(old)) {
      std::error_code ec;
      fs::permissions(s.temporary, old.permissions(), fs::perm_options::replace, ec);
      if (ec)
        throw IoError("cannot copy the permissions of " + s.final.string() + ": " + ec.message(),
                      path.string());
    }
    staged_.push_back(std::move(s));
  } catch (...) {
    if (out.is_open()) out.close();
    remove_quietly(s.temporary);
    release_slot(s.slot);
    throw;
  }
}

void FileBatch::commit() {
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    Staged& s = staged_[i];
    // rename replaces the target in one step, so readers see either the old or the new file, never a mix.
    std::error_code ec;
    fs::rename(s.temporary, s.final, ec);
    if (ec) {
      const std::string message = "cannot move " + s.temporary.string() + " into place: " + ec.message();
      const std::string target = s.target.string();
      staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(i));
      discard();
      throw IoError(message, target);
    }
    release_slot(s.slot);
  }
  staged_.clear();
}

void write_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write, bool binary) {
  FileBatch batch;
  batch.stage(path, write, binary);
  batch.commit();
}

void remove_temporary_files() {
  for (int i = 0; i < slot_count; ++i) {
    if (slot_used[i].load(std::memory_order_acquire)) DLFL_UNLINK(slot_names[i]);
  }
}

namespace {
void remove_temporary_files_and_stop(int signal) {
  remove_temporary_files();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}
}  // namespace

void remove_temporary_files_on_signals() {
  for (int signal : {
         SIGINT, SIGTERM
#if defined(SIGHUP)
             ,
             SIGHUP
#endif
       })
    std::signal(signal, remove_temporary_files_and_stop);
}

}  // namespace dlfl

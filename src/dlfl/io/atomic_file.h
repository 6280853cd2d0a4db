#pragma once
// Atomic file replacement: write everything to a temporary file beside the target, then rename it into place.
// A FileBatch does that for several files at once, so that a command's outputs are all replaced or none.

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace dlfl {

/// The file that writing to `path` replaces: `path` itself, or, when it is a symbolic link, the file the link
/// leads to (links are followed, so a linked output is written through its link and the link stays). Relative
/// link targets are taken from the link's folder.
std::filesystem::path write_target(const std::filesystem::path& path);

/// Throws IoError naming `path` if writing to it must fail: its folder is missing or not writable, or it is a
/// folder, not a regular file, or read-only (no write permission bit at all; refused even for root, who could
/// otherwise write it). Cheap: meant to be called on every output before any long work.
void check_writable(const std::filesystem::path& path);

/// Files replaced together. `stage` writes one file's new content to a temporary file beside its target;
/// `commit` renames every staged file into place. Destroyed without `commit` (say, because a later stage
/// threw), the batch removes its temporary files and leaves every target as it was. A replaced file keeps its
/// permission bits, and a symbolic link is written through (`write_target`).
///
/// While a batch holds temporary files, `remove_temporary_files()` (and the signal handlers installed by
/// `remove_temporary_files_on_signals`) can delete them. Each batch is used by one thread at a time.
class FileBatch {
 public:
  FileBatch() = default;
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;
  ~FileBatch();

  /// Calls `write` with a stream on a new temporary file beside `write_target(path)` and closes it. Throws
  /// IoError naming `path` when the file cannot be written (`check_writable`, a full disk, ...); whatever
  /// `write` throws propagates. Either way that file is not staged and its temporary is removed.
  void stage(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
             bool binary = false);

  /// Renames every staged file into place, in the order staged. Renaming within one folder replaces the
  /// target in one step. Throws IoError if a rename fails; the targets renamed before it are then replaced
  /// and the rest are not, and no temporary file is left.
  void commit();

  /// The number of staged files.
  std::size_t size() const { return staged_.size(); }

 private:
  struct Staged {
    std::filesystem::path target;     // the path given to stage, for messages
    std::filesystem::path final;      // write_target(target)
    std::filesystem::path temporary;  // beside `final`
    int slot;                         // in the registry of temporary files (atomic_file.cpp)
  };
  void discard();
  std::vector<Staged> staged_;
};

/// Calls `write` with a stream on a temporary file in the folder of `path`, flushes it, and renames it to
/// `path`: a FileBatch of one file. If `write` throws or any step fails, the temporary file is removed,
/// `path` is left as it was, and the exception propagates (failures of the file system become IoError naming
/// `path`).
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                      bool binary = false);

/// Removes the temporary files of every live FileBatch of the process (they are then lost: their batches'
/// commits fail). Async-signal-safe, so a signal handler may call it.
void remove_temporary_files();

/// Installs handlers for SIGINT, SIGTERM and SIGHUP that call `remove_temporary_files()` and then end the
/// process as the signal would have. For programs (the `dlfl` tool) that want no temporary file left behind
/// when they are stopped; the library never installs them itself.
void remove_temporary_files_on_signals();

}  // namespace dlfl

#pragma once
// Atomic file replacement: write everything to a temporary file beside the target, then rename it into place.

#include <filesystem>
#include <functional>
#include <iosfwd>

namespace dlfl {

/// Calls `write` with a stream on a temporary file in the folder of `path`, flushes it, and renames it to
/// `path`. If `write` throws or any step fails, the temporary file is removed, `path` is left as it was, and
/// the exception propagates (failures of the file system become IoError naming `path`).
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                      bool binary = false);

}  // namespace dlfl

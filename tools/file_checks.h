#pragma once
// The checks every command makes on the files it names, before any work: each output can be written, and no
// file is named twice (an input as an output, the mesh output as the log).

#include <string>
#include <vector>

#include <dlfl/errors.h>

namespace dlfl::tool {

/// The command line itself is at fault (exit 2), for a reason the library does not know of.
class UsageError : public InvalidArgument {
 public:
  using InvalidArgument::InvalidArgument;
};

/// A file a command names, with its role on the command line ("IN", "-o", "--log"); empty paths are unused
/// options and are skipped.
struct NamedFile {
  std::string role;
  std::string path;
};

/// Throws UsageError if two of the files are the same file: the same path, two spellings of one path, links
/// to one file, or hard links (compared through their real paths, links followed). Then throws IoError if an
/// output cannot be written (dlfl::check_writable).
void check_files(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

}  // namespace dlfl::tool

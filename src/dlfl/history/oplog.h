#pragma once
// Operation logs: an editor's session as a versioned JSON document ("format": "dlfl-oplog"), written and read
// from the operations' declarations, and replayed. Format: docs/oplog.md. This file is the one home of the
// log's JSON conversion.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include <dlfl/errors.h>
#include <dlfl/history/editor.h>

namespace dlfl {

class FileBatch;

/// The log version this library writes. Version 1 logs (written before the operation registry) and version 2
/// logs (written before the schemes' boundary rules) still replay: a parameter that did not exist then means
/// what it did before (`ParamSpec::in_old_logs`; a scheme's `boundary` is `hole`).
inline constexpr int oplog_version = 3;

/// A log that cannot be replayed. `op()` is the index of the offending op (or npos for the document itself)
/// and `field()` the field at fault ("corner1", "params.t"); the message names both.
class LogError : public IoError {
 public:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  LogError(const std::string& name, std::size_t op, const std::string& field, const std::string& what);
  std::size_t op() const { return op_; }
  const std::string& field() const { return field_; }

 private:
  std::size_t op_;
  std::string field_;
};

/// The editor's session as log text (JSON, one op per entry), with the hash of its final mesh
/// ("final_hash").
std::string log_text(const Editor& editor);

/// Writes `log_text(editor)` to a file atomically; with a `batch`, only stages it there (io/atomic_file.h),
/// to be replaced when the batch commits, together with its other files.
void write_log(const Editor& editor, const std::filesystem::path& path, FileBatch* batch = nullptr);

struct ReplayOptions {
  /// Check the hashes the log carries: of each loaded mesh (a `load` op's "hash": the file read again must
  /// hold the same mesh) and of the final mesh ("final_hash"). Off, they are ignored, and the replay uses the
  /// input files as they are now.
  bool verify = true;
  /// Called after each op has run, with the editor and the op's index: `editor.log().back()` is that op as
  /// the editor recorded it. For callers that want every intermediate mesh (the viewer's steps); what it
  /// throws ends the replay.
  std::function<void(const Editor& editor, std::size_t op)> after_op;
};

/// Replays log text in a fresh editor (with the log's undo limit) and returns it; `name` is used in
/// messages. Every op's parameters are checked against its declaration before it runs. Throws LogError for
/// bad JSON, a bad version or format, an unknown op, an unknown, missing, mistyped or out-of-range field, a
/// handle that does not exist at that point, or an op that fails; and, when verifying, for a loaded mesh
/// that has changed since the log was written (that op, field "hash") or a final mesh of another hash (field
/// "final_hash").
Editor replay_log(std::string_view text, const std::string& name = "log", const ReplayOptions& options = {});

/// Reads a log file and replays it. Throws IoError if the file cannot be read, else as above.
Editor replay_log_file(const std::filesystem::path& path, const ReplayOptions& options = {});

}  // namespace dlfl

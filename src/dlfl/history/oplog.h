#pragma once
// Operation logs: writing an editor's session to a versioned JSON file, and replaying one. Format:
// docs/oplog.md.

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/history/editor.h>

namespace dlfl {

/// A log that cannot be replayed. `op()` is the index of the offending op (or npos for the document itself)
/// and `field()` the field at fault; the message names both.
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

/// Replays a log document in a fresh editor (with the log's undo limit) and returns it; `name` is used in
/// messages. Throws LogError for a bad version or format, an unknown op, a missing or mistyped field, a
/// handle that does not exist at that point, or an op that fails.
Editor replay_log(const nlohmann::json& log, const std::string& name = "log");

/// Reads a log file and replays it. Throws IoError if the file cannot be read or is not JSON, else as above.
Editor replay_log_file(const std::filesystem::path& path);

/// Writes `editor.log()` to a file atomically.
void write_log(const Editor& editor, const std::filesystem::path& path);

}  // namespace dlfl

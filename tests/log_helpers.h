#pragma once
// Operation logs as JSON documents in tests: the library hands out log text; tests that edit a log by hand
// parse it, change it and replay its text.

#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>

namespace dlfl::test {

inline nlohmann::json log_json(const dlfl::Editor& editor) {
  return nlohmann::json::parse(dlfl::log_text(editor));
}

inline dlfl::Editor replay_json(const nlohmann::json& log, const std::string& name = "log") {
  return dlfl::replay_log(log.dump(), name);
}

}  // namespace dlfl::test

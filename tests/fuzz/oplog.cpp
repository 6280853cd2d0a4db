// Operation logs (dlfl/history/oplog.h): parse and replay; a log that replays must, written again, replay to
// an equal mesh. Logs that would read a file or subdivide more than fuzz::max_log_steps times are skipped
// (log_guard.h).

#include <nlohmann/json.hpp>

#include <dlfl/errors.h>
#include <dlfl/history/oplog.h>
#include <dlfl/validate.h>

#include "fuzz_common.h"
#include "log_guard.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > 16 * 1024) return 0;
  const std::string_view text = fuzz::text_of(data, size);
  if (fuzz::refuse_log(nlohmann::json::parse(text, nullptr, false))) return 0;
  std::string again;
  try {
    const Editor editor = replay_log(text, fuzz::input_name);
    const ValidationReport report = validate(editor.mesh(), 1);
    if (!report.valid())
      fuzz::finding("the replayed mesh does not validate: " + report.violations.at(0).message);
    again = log_text(editor);
    if (fuzz::refuse_log(nlohmann::json::parse(again, nullptr, false))) return 0;
    try {
      fuzz::check(replay_log(again, "rewritten").mesh() == editor.mesh(),
                  "the log written after a replay replays to a different mesh");
    } catch (const Error& e) {
      fuzz::finding(std::string("the log written after a replay does not replay: ") + e.what());
    }
  } catch (const Error&) {
  }
  return 0;
}

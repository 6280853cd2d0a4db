// `dlfl edit --op 'NAME key=value ...'` strings (parse_operation_text, dlfl/operations/operation_text.h):
// each line of the input is one --op, resolved (resolve_operation_params) against the current mesh and
// applied through an Editor that starts on the cube. Checked: an op that fails leaves the mesh and the log as
// they were; every mesh validates; the log replays to an equal mesh; undoing everything gives the cube back.
// `load` ops (they read files) end the input, and subdivision stops at fuzz::max_edit_steps steps in all.

#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/operation_text.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>
#include <dlfl/validate.h>

#include "fuzz_common.h"
#include "small_meshes.h"

namespace dlfl::fuzz {
inline constexpr std::size_t max_edit_steps = 3;
inline constexpr std::size_t max_edit_ops = 16;
}  // namespace dlfl::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > 4096) return 0;
  Editor editor;
  editor.set_mesh(fuzz::cube());
  editor.clear_history();  // the cube is where undo stops
  std::size_t steps = 0;
  bool history_cleared = false;
  for (std::string_view line : fuzz::lines_of(fuzz::text_of(data, size), fuzz::max_edit_ops)) {
    const Mesh before = editor.mesh();
    const std::size_t logged = editor.log().size();
    try {
      const auto [name, given] = parse_operation_text(line);
      const OperationSpec& spec = find_operation(name);
      if (name == "load") break;  // reads a file
      const Params resolved = resolve_operation_params(spec, given, editor.mesh());
      if (name == "subdivide") {
        std::size_t per_iteration = 1;
        if (resolved.text("scheme") == "mhp") {
          per_iteration = expand_mhp_pattern(resolved.get("params").as_params().text("pattern")).size();
        }
        steps += static_cast<std::size_t>(resolved.integer("iterations")) * per_iteration;
        if (steps > fuzz::max_edit_steps) break;
      }
      editor.apply(name, given);
      history_cleared = history_cleared || name == "clear_history";
    } catch (const Error&) {
      fuzz::check(editor.mesh() == before, "a failed op changed the mesh");
      fuzz::check(editor.log().size() == logged, "a failed op changed the log");
      continue;
    }
    const ValidationReport report = validate(editor.mesh(), 1);
    if (!report.valid()) fuzz::finding("an op made an invalid mesh: " + report.violations.at(0).message);
  }
  try {
    fuzz::check(replay_log(log_text(editor), "rewritten").mesh() == editor.mesh(),
                "the log replays to a different mesh");
  } catch (const Error& e) {
    fuzz::finding(std::string("the log does not replay: ") + e.what());
  }
  if (history_cleared) return 0;
  try {
    while (editor.group_depth() > 0) editor.end_group();
    while (editor.undo()) {
    }
  } catch (const Error& e) {
    fuzz::finding(std::string("undoing everything failed: ") + e.what());
  }
  fuzz::check(editor.mesh() == fuzz::cube(), "undoing everything does not give the cube back");
  return 0;
}

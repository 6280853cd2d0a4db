// dlfl edit IN -o OUT --op 'NAME key=value ...' [--op ...] [--log LOG.json [--self-contained]]
// Applies registered operations in order; nothing is written unless every one of them succeeds.

#include <chrono>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/operations/operation_text.h>
#include "commands.h"
#include "editor_session.h"
#include "feedback.h"

namespace dlfl::tool {

Action add_edit(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "edit", "Apply operations (dlfl ops lists them) in order, writing nothing unless all succeed");
  struct Args {
    EditorFiles files;
    std::vector<std::string> ops;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("IN", a->files.in, "Input mesh (.obj, .off, .ply, .stl, .json)")->required();
  add_output_options(cmd, a->files, "Output mesh (format by extension; .json keeps every handle)",
                     "Write PLY or STL as ASCII instead of binary");
  cmd->add_option(
         "--op", a->ops,
         "An operation: 'NAME key=value ...' (repeatable, applied in order). A handle is its number, "
         "a point x,y,z, a list a,b,c; params.KEY=VALUE sets a scheme parameter of subdivide")
      ->required();
  return [a] {
    check_editor_files(a->files);
    // Every op string is parsed before the input is read: a typo costs nothing.
    std::vector<std::pair<std::string, Params>> ops;
    for (const auto& text : a->ops) ops.push_back(parse_operation_text(text));
    Editor editor = open_editor(a->files);
    for (std::size_t i = 0; i < ops.size(); ++i) {
      try {
        const auto start = std::chrono::steady_clock::now();
        editor.apply(ops[i].first, ops[i].second);
        const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
        say("--op " + std::to_string(i + 1) + " " + ops[i].first + ": " + counts_text(editor.mesh()) +
            " in " + seconds_text(seconds.count()));
      } catch (const ParameterError& e) {
        throw ParameterError("--op " + std::to_string(i + 1) + ": " + e.what(), e.parameter());
      } catch (const UnknownNameError& e) {
        throw UnknownNameError("--op " + std::to_string(i + 1) + ": " + e.what(), e.suggestion());
      } catch (const TopologyError& e) {
        throw TopologyError("--op " + std::to_string(i + 1) + " (" + ops[i].first + "): " + e.what());
      } catch (const IoError&) {
        throw;
      } catch (const InvalidArgument& e) {
        throw InvalidArgument("--op " + std::to_string(i + 1) + " (" + ops[i].first + "): " + e.what());
      }
    }
    save_editor(editor, a->files);
    return ok;
  };
}

}  // namespace dlfl::tool

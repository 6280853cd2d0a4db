// dlfl replay LOG.json -o OUT

#include <string>

#include <dlfl/history/oplog.h>
#include <dlfl/io/mesh_io.h>
#include "commands.h"
#include "feedback.h"
#include "file_checks.h"

namespace dlfl::tool {

Action add_replay(CLI::App& app) {
  auto* cmd = app.add_subcommand("replay", "Replay an operation log and write the resulting mesh");
  auto log = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto ascii = std::make_shared<bool>(false);
  auto no_verify = std::make_shared<bool>(false);
  cmd->add_option("LOG", *log, "Operation log (.json)")->required();
  cmd->add_option("-o,--output", *out, "Output mesh (format by extension; .json keeps every handle)")
      ->required();
  cmd->add_flag("--ascii", *ascii, "Write PLY or STL as ASCII instead of binary");
  cmd->add_flag("--no-verify", *no_verify,
                "Do not check the hashes the log carries (of each input read again, and of the final mesh)");
  return [log, out, ascii, no_verify] {
    check_files({{"LOG", *log}}, {{"-o", *out}});
    ReplayOptions options;
    options.verify = !*no_verify;
    FileReport replaying("replay", *log);
    const Editor editor = [&] {
      StepReport steps(0, 0);
      return replay_log_file(*log, options);
    }();
    replaying.done(editor.mesh());  // nothing is written unless the whole log replays
    WriteOptions write;
    write.binary = !*ascii;
    FileReport writing("write", *out);
    write_mesh(editor.mesh(), *out, write);
    writing.done(editor.mesh());
    return ok;
  };
}

}  // namespace dlfl::tool

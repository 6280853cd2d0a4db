#include "editor_session.h"

#include "feedback.h"
#include "file_checks.h"

#include <dlfl/history/oplog.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/mesh_io.h>

namespace dlfl::tool {

void add_output_options(CLI::App* cmd, EditorFiles& files, const std::string& output_help,
                        const std::string& ascii_help) {
  cmd->add_option("-o,--output", files.out, output_help)->required();
  cmd->add_option("--log", files.log, "Write the operation log (JSON) here");
  cmd->add_flag("--self-contained", files.self_contained,
                "Embed the input mesh in the log so it replays anywhere");
  cmd->add_flag("--ascii", files.ascii, ascii_help);
}

void check_editor_files(const EditorFiles& files) {
  check_files({{"IN", files.in}}, {{"-o", files.out}, {"--log", files.log}});
}

Editor open_editor(const EditorFiles& files) {
  Editor::Options options;
  options.embed_meshes = files.self_contained;
  Editor editor(options);
  FileReport report("read", files.in);
  editor.set_mesh(read_mesh(files.in), files.in);
  report.done(editor.mesh());
  return editor;
}

void save_editor(const Editor& editor, const EditorFiles& files) {
  // Both files or neither: each is staged, and only when both are complete do they replace their targets.
  FileReport report("write", files.log.empty() ? files.out : files.out + " and " + files.log);
  FileBatch batch;
  WriteOptions write;
  write.binary = !files.ascii;
  write.batch = &batch;
  write_mesh(editor.mesh(), files.out, write);
  if (!files.log.empty()) write_log(editor, files.log, &batch);
  batch.commit();
  report.done(editor.mesh());
}

}  // namespace dlfl::tool

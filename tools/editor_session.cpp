#include "editor_session.h"

#include "feedback.h"

#include <dlfl/history/oplog.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/mesh_io.h>

namespace dlfl::tool {

Editor open_editor(const std::string& in, bool self_contained) {
  Editor::Options options;
  options.embed_meshes = self_contained;
  Editor editor(options);
  FileReport report("read", in);
  editor.set_mesh(read_mesh(in), in);
  report.done(editor.mesh());
  return editor;
}

void save_editor(const Editor& editor, const std::string& out, bool ascii, const std::string& log) {
  // Both files or neither: each is staged, and only when both are complete do they replace their targets.
  FileReport report("write", log.empty() ? out : out + " and " + log);
  FileBatch batch;
  WriteOptions write;
  write.binary_ply = !ascii;
  write.batch = &batch;
  write_mesh(editor.mesh(), out, write);
  if (!log.empty()) write_log(editor, log, &batch);
  batch.commit();
  report.done(editor.mesh());
}

}  // namespace dlfl::tool

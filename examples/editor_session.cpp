// An editing session: operations by name, grouped into one undo entry, a subdivision step, undo and redo,
// and an operation log that replays to the same mesh. Usage: example_editor_session [DATA_DIR]
#include <dlfl/dlfl.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : "data";
  dlfl::Editor editor(dlfl::Editor::Options{true, 0});  // self-contained log
  editor.set_mesh(dlfl::read_mesh(data + "/cube.obj"), data + "/cube.obj");

  editor.begin_group("cut a corner");
  const dlfl::CornerId c = editor.mesh().first_corner(dlfl::FaceId(0));
  const auto cut =
      editor.apply("insert_edge", {{"corner1", c}, {"corner2", editor.mesh().next(editor.mesh().next(c))}});
  editor.apply("subdivide_edge", {{"edge", cut.get("edge")}});  // at the midpoint, the default
  editor.end_group();
  editor.subdivide("catmull-clark", {}, 1);
  editor.undo();  // back to the cut cube, exactly
  editor.redo();

  for (const auto& entry : editor.undo_history()) {
    std::printf("history: %s (%zu operations)\n", entry.label.c_str(), entry.operations);
  }
  const dlfl::Editor replayed = dlfl::replay_log(dlfl::log_text(editor));
  const bool same = dlfl::mesh_hash(replayed.mesh()) == dlfl::mesh_hash(editor.mesh());
  std::printf("faces %zu, log replays to the same mesh: %s\n", editor.mesh().num_faces(),
              same ? "yes" : "no");
  return same ? 0 : 1;
}

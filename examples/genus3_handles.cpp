// Modeling a genus-3 object from a cube: its top extruded into a tower, three handles (curved tubes) from
// the cube's sides up to the tower's, and two Catmull-Clark steps. Every step is an editor operation, so the
// whole model is undoable and its log replays it. Writes genus3_handles.obj and genus3_handles.log.json
// (the log is data/genus3_handles.log.json of the repository, which `dlfl replay` runs).
// Usage: example_genus3_handles [DATA_DIR] [OUTPUT_DIR]
#include <dlfl/dlfl.h>
#include "model_report.h"

#include <glm/geometric.hpp>
#include <string>

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : "data";
  const std::string out = argc > 2 ? argv[2] : ".";
  dlfl::Editor editor(dlfl::Editor::Options{true, 0});  // a self-contained log: the cube is in it
  editor.set_mesh(dlfl::read_mesh(data + "/cube.obj"), "cube.obj");

  // The tower: the top face (z = 1) moved up by 1.5, with side quads joining it to where it was.
  editor.apply("extrude_face",
               {{"face", example::face_nearest(editor.mesh(), {0, 0, 1})}, {"distance", 1.5}});

  // Three handles, each a tube of 8 rings from a side of the cube (centroid at z = 0) to the tower's side
  // above it (z = 1.75), curving out along the two faces' normals.
  editor.begin_group("three handles");
  for (const glm::dvec3 side : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0)}) {
    editor.apply("connect_faces",
                 {{"face1", example::face_nearest(editor.mesh(), side)},
                  {"face2", example::face_nearest(editor.mesh(), side + glm::dvec3(0, 0, 1.75))},
                  {"segments", 8},
                  {"curve", "hermite"},
                  {"weight1", 1.5},
                  {"weight2", 1.5}});
  }
  editor.end_group();
  editor.subdivide("catmull-clark", {}, 2);

  // The counts and the genus as tests/test_modeling_tool.cpp derives them by hand.
  const dlfl::Mesh cube = dlfl::read_mesh(data + "/cube.obj");
  return example::report_model(editor, out, "genus3_handles", cube, 3, {1596, 3200, 1600}, 3) ? 0 : 1;
}

// A rind-modelled lantern: a cube rounded by two Catmull-Clark steps, hollowed into a shell of thickness
// 0.15 with one window punched through each of its six sides (rind), then smoothed by one more
// Catmull-Clark step. Every step is an editor operation, so the model is undoable and its log replays it.
// Writes rind_lantern.obj and rind_lantern.log.json (the log is data/rind_lantern.log.json of the
// repository, which `dlfl replay` runs).
//
// The counts follow from the closed forms (docs/modeling.md): the cube (V 8, E 12, F 6) after two
// Catmull-Clark steps has V 98, E 192, F 96; rind with k = 6 quads doubles it and adds 4k edges and 2k
// faces (V 196, E 408, F 204, Euler characteristic 2*2 - 2*6 = -8, genus 5); the last step gives
// V + E + F = 808 vertices, 2E + 4F = 1632 edges and 4F = 816 quads, the genus unchanged.
// Usage: example_rind_lantern [DATA_DIR] [OUTPUT_DIR]
#include <dlfl/dlfl.h>
#include "model_report.h"

#include <string>
#include <vector>

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : "data";
  const std::string out = argc > 2 ? argv[2] : ".";
  dlfl::Editor editor(dlfl::Editor::Options{true, 0});  // a self-contained log: the cube is in it
  editor.set_mesh(dlfl::read_mesh(data + "/cube.obj"), "cube.obj");
  editor.subdivide("catmull-clark", {}, 2);

  // One window per side: of the four quads around the side's centre, the one towards +,+ of the other two
  // axes (so that no two windows share a vertex).
  std::vector<dlfl::FaceId> windows;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      glm::dvec3 target(0.3);
      target[axis] = sign;
      windows.push_back(example::face_nearest(editor.mesh(), target));
    }
  }
  editor.apply("rind", {{"faces", windows}, {"thickness", 0.15}});
  editor.subdivide("catmull-clark", {}, 1);

  const dlfl::Mesh cube = dlfl::read_mesh(data + "/cube.obj");
  return example::report_model(editor, out, "rind_lantern", cube, 3, {808, 1632, 816}, 5) ? 0 : 1;
}

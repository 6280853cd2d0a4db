// A wireframe dodecahedron: every edge of the dodecahedron a beam of depth 0.15, every face an opening
// (wireframe, with the openings 0.15 inside the edges), then one Catmull-Clark step to round the beams.
// Writes wireframe_dodecahedron.obj and wireframe_dodecahedron.log.json (the log is
// data/wireframe_dodecahedron.log.json of the repository, which `dlfl replay` runs).
//
// The counts follow from the closed forms (docs/modeling.md): the dodecahedron has V 20, E 30, F 12;
// wireframe gives 2V + 4E = 160 vertices, 12E = 360 edges and 6E = 180 quads, one component of genus
// E - V + 1 = 11; Catmull-Clark then gives V + E + F = 700 vertices, 2E + 4F = 1440 edges and 4F = 720
// quads, the genus unchanged.
// Usage: example_wireframe_dodecahedron [DATA_DIR] [OUTPUT_DIR]
#include <dlfl/dlfl.h>
#include "model_report.h"

#include <string>

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : "data";
  const std::string out = argc > 2 ? argv[2] : ".";
  dlfl::Editor editor(dlfl::Editor::Options{true, 0});  // a self-contained log: the dodecahedron is in it
  const dlfl::Mesh dodecahedron = dlfl::read_mesh(data + "/dodecahedron.obj");
  editor.set_mesh(dodecahedron, "dodecahedron.obj");
  editor.apply("wireframe", {{"thickness", 0.15}, {"width", 0.15}});
  editor.subdivide("catmull-clark", {}, 1);

  return example::report_model(editor, out, "wireframe_dodecahedron", dodecahedron, 2, {700, 1440, 720}, 11)
             ? 0
             : 1;
}

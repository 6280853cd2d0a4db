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

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : "data";
  const std::string out = argc > 2 ? argv[2] : ".";
  dlfl::Editor editor(dlfl::Editor::Options{true, 0});  // a self-contained log: the dodecahedron is in it
  const dlfl::Mesh dodecahedron = dlfl::read_mesh(data + "/dodecahedron.obj");
  editor.set_mesh(dodecahedron, "dodecahedron.obj");
  editor.apply("wireframe", {{"thickness", 0.15}, {"width", 0.15}});
  editor.subdivide("catmull-clark", {}, 1);

  const dlfl::Mesh& mesh = editor.mesh();
  const dlfl::ValidationReport report = dlfl::validate(mesh);
  const long genus = report.valid() && report.components.size() == 1 ? report.components[0].genus : -1;
  std::printf("V %zu, E %zu, F %zu, genus %ld\n", mesh.num_vertices(), mesh.num_edges(), mesh.num_faces(),
              genus);
  dlfl::write_mesh(mesh, out + "/wireframe_dodecahedron.obj");
  dlfl::write_log(editor, out + "/wireframe_dodecahedron.log.json");

  // The log replays to the same mesh, and undoing the two steps gives the dodecahedron back.
  const bool replays =
      dlfl::mesh_hash(dlfl::replay_log(dlfl::log_text(editor)).mesh()) == dlfl::mesh_hash(mesh);
  for (int i = 0; i < 2; ++i) editor.undo();
  const bool undone = editor.mesh() == dodecahedron;
  std::printf("log replays to the same mesh: %s; undo gives the dodecahedron back: %s\n",
              replays ? "yes" : "no", undone ? "yes" : "no");
  const bool counts = mesh.num_vertices() == 700 && mesh.num_edges() == 1440 && mesh.num_faces() == 720;
  return genus == 11 && counts && replays && undone ? 0 : 1;
}

// An outside program that includes only <dlfl/dlfl.h> from the installed library: per-element containers,
// a named attribute, and the editor's groups. Exit 0 when every check holds.
#include <dlfl/dlfl.h>

#include <cstdio>
#include <vector>

int main() {
  dlfl::Editor editor;
  std::vector<glm::dvec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  editor.begin_group("square");
  editor.create_face_manifold(square);
  editor.end_group();
  const dlfl::Mesh& mesh = editor.mesh();
  bool ok = dlfl::validate(mesh).valid() && mesh.num_faces() == 2 && mesh.num_edges() == 4;
  ok = ok && editor.undo_history().size() == 1 && editor.undo_history()[0].label == "square";

  dlfl::FaceData<int> sides(mesh, 0);
  for (dlfl::FaceId f : mesh.faces()) sides[f] = static_cast<int>(mesh.size(f));
  dlfl::VertexData<double> height(mesh);
  for (dlfl::VertexId v : mesh.vertices()) height[v] = mesh.position(v).x + mesh.position(v).y;
  ok = ok && sides[dlfl::FaceId(0)] == 4 && height[dlfl::VertexId(2)] == 2.0;

  dlfl::Mesh copy = mesh;
  auto weight = copy.add_vertex_attribute<double>("weight", 1.0);
  weight[dlfl::VertexId(1)] = 3.0;
  ok = ok && copy.vertex_attribute<double>("weight")[dlfl::VertexId(1)] == 3.0 &&
       copy.vertex_attribute<double>("weight")[dlfl::VertexId(0)] == 1.0;

  try {
    dlfl::read_mesh("no such file.obj");
    ok = false;
  } catch (const dlfl::Error&) {
  }
  ok = ok && editor.undo() && editor.mesh().num_faces() == 0;
  std::printf("%s\n", ok ? "consumer ok" : "consumer FAILED");
  return ok ? 0 : 1;
}

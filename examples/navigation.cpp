// Navigation: reads a mesh and walks it the way a modelling tool does — the neighbours of a vertex, the
// faces around it, the edge between two vertices, normals and areas. Usage: example_navigation [DATA_DIR]
#include <dlfl/dlfl.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : "data";
  const dlfl::Mesh mesh = dlfl::read_mesh(data + "/dodecahedron.obj");
  const dlfl::VertexId v(0);
  std::printf("vertex 0 at (%g, %g, %g), valence %u\n", mesh.position(v).x, mesh.position(v).y,
              mesh.position(v).z, mesh.valence(v));
  for (dlfl::VertexId w : dlfl::neighbours(mesh, v)) {
    const dlfl::EdgeId e = dlfl::find_edge(mesh, v, w);
    std::printf("  neighbour %u along edge %u\n", w.index(), e.index());
  }
  double area = 0;
  for (dlfl::FaceId f : dlfl::faces(mesh, v)) area += dlfl::face_area(mesh, f);
  const glm::dvec3 n = dlfl::vertex_normal(mesh, v);
  std::printf("  area of its faces %.6f, normal (%.4f, %.4f, %.4f)\n", area, n.x, n.y, n.z);
  // Every face of a dodecahedron is a pentagon with 5 neighbours across its edges.
  for (dlfl::FaceId f : dlfl::surface_faces(mesh)) {
    int across = 0;
    for ([[maybe_unused]] dlfl::FaceId g : dlfl::neighbours(mesh, f)) ++across;
    if (across != 5) return 1;
  }
  return mesh.num_surface_faces() == 12 ? 0 : 1;
}

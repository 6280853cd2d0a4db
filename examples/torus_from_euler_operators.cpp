// A torus built with the Euler operators alone: a square face manifold (a two-sided square), then an
// INSERTEDGE between its two faces makes a handle (genus 1), and more INSERTEDGEs split the faces. The
// validator proves each step leaves a 2-manifold. Usage: example_torus_from_euler_operators
#include <dlfl/dlfl.h>

#include <cstdio>

int main() {
  dlfl::Mesh mesh;
  const glm::dvec3 square[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  dlfl::VertexId v[4];
  dlfl::CornerId front[4], back[4];
  dlfl::create_face_manifold(mesh, square, v, front, back);
  // One edge from the front face to the back face merges them: the genus goes from 0 to 1.
  const dlfl::InsertEdgeResult handle = mesh.insert_edge(front[0], back[2]);
  std::printf("after the handle: V %zu, E %zu, F %zu, genus %ld\n", mesh.num_vertices(), mesh.num_edges(),
              mesh.num_faces(), dlfl::validate(mesh).components.at(0).genus);
  // Splitting the merged face keeps the genus and adds faces.
  const dlfl::FaceId merged = mesh.face(front[1]);
  const dlfl::CornerId c = mesh.first_corner(merged);
  mesh.insert_edge(c, mesh.next(mesh.next(c)));
  const auto report = dlfl::validate(mesh);
  std::printf("after a split: V %zu, E %zu, F %zu, genus %ld, valid %s\n", mesh.num_vertices(),
              mesh.num_edges(), mesh.num_faces(), report.components.at(0).genus,
              report.valid() ? "yes" : "no");
  return report.valid() && report.components.at(0).genus == 1 && handle.removed_face.valid() ? 0 : 1;
}

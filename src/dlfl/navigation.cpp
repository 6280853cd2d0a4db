#include <dlfl/navigation.h>

#include <dlfl/errors.h>

namespace dlfl {
namespace {
template <class H>
void require(const Mesh& mesh, H h, const char* op) {
  if (!mesh.is_alive(h)) throw InvalidArgument(std::string(op) + ": " + to_string(h) + " does not exist");
}
}  // namespace

EdgeId find_edge(const Mesh& mesh, VertexId u, VertexId v) {
  require(mesh, u, "find_edge");
  require(mesh, v, "find_edge");
  for (CornerId c : mesh.corners(u)) {
    if (mesh.edge(c).valid() && mesh.vertex(mesh.next(c)) == v) return mesh.edge(c);
  }
  return EdgeId();
}

CornerId corner_in_face(const Mesh& mesh, VertexId v, FaceId f) {
  require(mesh, v, "corner_in_face");
  require(mesh, f, "corner_in_face");
  for (CornerId c : mesh.corners(v)) {
    if (mesh.face(c) == f) return c;
  }
  return CornerId();
}

bool is_boundary(const Mesh& mesh, VertexId v) {
  require(mesh, v, "is_boundary");
  for (FaceId f : faces(mesh, v)) {
    if (mesh.is_hole(f)) return true;
  }
  return false;
}

bool is_boundary(const Mesh& mesh, EdgeId e) {
  require(mesh, e, "is_boundary");
  return mesh.is_hole(mesh.face(e, 0)) || mesh.is_hole(mesh.face(e, 1));
}

}  // namespace dlfl

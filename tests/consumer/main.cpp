// Builds a face manifold with the installed library and checks it; exit 0 on success.
#include <dlfl/create_face_manifold.h>
#include <dlfl/validate.h>
#include <dlfl/io/mesh_io.h>

#include <cstdio>
#include <vector>

int main() {
  dlfl::Mesh mesh;
  std::vector<glm::dvec3> points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  dlfl::create_face_manifold(mesh, points);
  const auto report = dlfl::validate(mesh);
  const bool ok =
      report.valid() && mesh.num_faces() == 2 && mesh.num_edges() == 4 && report.components.size() == 1;
  std::printf("%s\n", ok ? "consumer ok" : "consumer FAILED");
  return ok ? 0 : 1;
}

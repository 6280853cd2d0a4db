#include <dlfl/schemes/detail/vertex_faces.h>

#include <string>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>

namespace dlfl::detail {

void refuse_vertex_face(const Mesh& input, const char* scheme, std::uint32_t v, bool point_sphere) {
  const std::string vertex = to_string(original_handle<VertexId>(input, v));
  if (point_sphere) throw TopologyError(std::string(scheme) + ": " + vertex + " is a point sphere (no edge)");
  throw TopologyError(std::string(scheme) + ": " + vertex +
                      " has valence 1 (its face would have a single corner)");
}

}  // namespace dlfl::detail

#include <dlfl/schemes/detail/vertex_faces.h>

#include <string>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>

namespace dlfl::detail {

// Orientation. Let c be a corner at v in face f, p = prev(c). Seen from outside f is counter-clockwise, so at
// v its interior is the angle swept counter-clockwise from the direction of edge(c) (towards next(c)) to that
// of edge(p) (towards vertex(p)). Turning further counter-clockwise crosses edge(p) into the face of
// opposite(p), whose corner at v is opposite(p) itself (it starts where p's edge ends): that is
// prev_around_vertex(c). So listing the corners around v along prev_around_vertex is counter-clockwise.
void number_vertex_face_corners(const Mesh& m, const Mesh& input, const char* scheme, std::uint32_t first,
                                std::span<std::uint32_t> offsets, std::span<std::uint32_t> slot,
                                bool refuse_valence_one) {
  const auto nv = static_cast<std::uint32_t>(m.num_vertices());
  std::uint32_t next_slot = first;
  for (std::uint32_t v = 0; v < nv; ++v) {
    offsets[v] = next_slot;
    const CornerId start = m.corner(VertexId(v));
    if (!m.edge(start).valid()) {
      throw TopologyError(std::string(scheme) + ": " + to_string(original_handle<VertexId>(input, v)) +
                          " is a point sphere (no edge)");
    }
    CornerId c = start;
    do {
      slot[c.index()] = next_slot++;
      c = m.prev_around_vertex(c);
    } while (c != start);
    if (refuse_valence_one && next_slot - offsets[v] == 1) {
      throw TopologyError(std::string(scheme) + ": " + to_string(original_handle<VertexId>(input, v)) +
                          " has valence 1 (its face would have a single corner)");
    }
  }
  offsets[nv] = next_slot;
}

}  // namespace dlfl::detail

#include <dlfl/schemes/catmull_clark.h>

#include <optional>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/quad_split.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {

Mesh catmull_clark(const Mesh& input, Origins* origins) {
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  const auto [nv, ne, nf, nc] = dense_counts(m);
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (m.is_point_sphere(VertexId(v))) {
      throw TopologyError("catmull-clark: " + to_string(VertexId(v)) + " is a point sphere (no edge)");
    }
  }
  const std::uint32_t edge_base = nv, face_base = nv + ne;
  MeshAssembler out(std::size_t(nv) + ne + nf, nc, 4);

  // Face points.
  detail::LargeVector<glm::dvec3> face_point(nf);
  for (std::uint32_t f = 0; f < nf; ++f) {
    glm::dvec3 sum(0.0);
    for (CornerId c : m.corners(FaceId(f))) sum += m.position(m.vertex(c));
    face_point[f] = sum / double(m.size(FaceId(f)));
    out.set_position(face_base + f, face_point[f]);
  }
  // Edge points.
  for (std::uint32_t e = 0; e < ne; ++e) {
    const EdgeId id(e);
    out.set_position(edge_base + e, (m.position(m.from(id)) + m.position(m.to(id)) +
                                     face_point[m.face(id, 0).index()] + face_point[m.face(id, 1).index()]) /
                                        4.0);
  }
  // Vertex points: (Q + 2R + (n-3) S) / n = (sum of face points + 2 sum of midpoints) / n^2 + (n-3) S / n.
  // Each corner at v contributes its face's point and the midpoint of its outgoing edge (each edge at v
  // leaves v at exactly one corner).
  detail::LargeVector<glm::dvec3> sums(nv, glm::dvec3(0.0));
  detail::LargeVector<std::uint32_t> valence(nv, 0);
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const std::uint32_t v = m.vertex(c).index();
    const glm::dvec3 mid = 0.5 * (m.position(VertexId(v)) + m.position(m.vertex(m.next(c))));
    sums[v] += face_point[m.face(c).index()] + 2.0 * mid;
    ++valence[v];
  }
  for (std::uint32_t v = 0; v < nv; ++v) {
    const double n = valence[v];
    out.set_position(v, sums[v] / (n * n) + (n - 3.0) / n * m.position(VertexId(v)));
  }
  // Quad k for corner k: (vertex point, edge point out, face point, edge point in).
  detail::assemble_quad_split(m, out);
  Mesh result = out.finish();
  if (origins) detail::quad_split_origins(m, result, detail::InputHandles(input), *origins);
  return result;
}

namespace detail {

SchemeSpec catmull_clark_scheme() {
  return parameterless_scheme(
      catmull_clark, "catmull-clark",
      "Catmull-Clark: a quad per corner; smooth (C2 away from extraordinary points) on any polygon mesh",
      [](const MeshCounts& c) {  // V' = V + E + F, E' = 2E + C = 4E, F' = C = 2E
        return MeshCounts{c.vertices + c.edges + c.faces, 4 * c.edges, 2 * c.edges};
      });
}

}  // namespace detail
}  // namespace dlfl

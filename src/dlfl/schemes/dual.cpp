#include <dlfl/schemes/dual.h>

#include <optional>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/corner_origins.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/scheme_table.h>
#include <dlfl/schemes/detail/vertex_faces.h>

namespace dlfl {

Mesh dual(const Mesh& input, Origins* origins) { return detail::dual(input, origins, nullptr); }

Mesh detail::dual(const Mesh& input, Origins* origins, std::vector<Origin>* corners) {
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  const auto [nv, ne, nf, nc] = dense_counts(m);

  for (std::uint32_t f = 0; f < nf; ++f) {
    if (m.is_hole(FaceId(f))) {
      throw TopologyError("dual: " + to_string(original_handle<FaceId>(input, f)) +
                          " is a hole: the dual of an open mesh is not defined");
    }
  }
  for (std::uint32_t e = 0; e < ne; ++e) {
    if (m.face(EdgeId(e), 0) == m.face(EdgeId(e), 1)) {
      throw TopologyError("dual: " + to_string(original_handle<EdgeId>(input, e)) +
                          " has the same face on both sides (its dual would be a self-loop)");
    }
  }

  // Output face v owns the corners offsets[v] .. offsets[v+1]-1: vslot[c] is the one for input corner c,
  // counter-clockwise around v, so that the dual face's normal points outward.
  std::vector<std::uint32_t> offsets(std::size_t(nv) + 1);
  std::vector<std::uint32_t> vslot(nc);
  detail::number_vertex_face_corners(m, input, "dual", 0, offsets, vslot, false);

  MeshAssembler out(nf, offsets);
  for (std::uint32_t f = 0; f < nf; ++f) {
    glm::dvec3 sum(0.0);
    for (CornerId c : m.corners(FaceId(f))) sum += m.position(m.vertex(c));
    out.set_position(f, sum / double(m.size(FaceId(f))));
  }

  // Twins. The dual corner of c (at v, in face f) runs from dual vertex f to dual vertex face(d), d =
  // opposite(p), p = prev(c): it crosses the input edge g = edge(p), which runs from w = vertex(p) to v. Its
  // twin is the dual corner in face w that crosses g from face(d) back to f: the corner c' at w in face(d)
  // whose prev has edge g, i.e. prev(c') = d, c' = next(d) = next(opposite(prev(c))). (Applying the rule to
  // c' gives next(opposite(d)) = next(p) = c back.)
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const CornerId twin = m.next(m.opposite(m.prev(c)));
    out.set_corner(vslot[k], m.face(c).index(), vslot[twin.index()]);
  }
  Mesh result = out.finish();
  if (origins || corners) {
    const detail::InputHandles in(input);
    if (corners) {
      corners->assign(nc, Origin{});
      for (std::uint32_t k = 0; k < nc; ++k) (*corners)[vslot[k]] = in.corner(k);
    }
    if (origins) {
      detail::reset_origins(*origins, result);
      for (std::uint32_t f = 0; f < nf; ++f) origins->vertices[f] = in.face(f);
      for (std::uint32_t v = 0; v < nv; ++v) origins->faces[v] = in.vertex(v);
      // The corner for c crosses edge(prev(c)) (see the twins above).
      std::vector<Origin> edge_of(nc);
      for (std::uint32_t k = 0; k < nc; ++k) edge_of[vslot[k]] = in.edge(m.edge(m.prev(CornerId(k))).index());
      detail::set_edge_origins(*origins, result, edge_of);
    }
  }
  return result;
}

namespace detail {

SchemeSpec dual_scheme() {
  return parameterless_scheme(
      dlfl::dual, "dual",
      "the dual mesh: a vertex per face (at its centroid), a face per vertex, an edge across every edge",
      [](const MeshCounts& c) {
        return MeshCounts{c.faces, c.edges, c.vertices};
      });
}

}  // namespace detail
}  // namespace dlfl

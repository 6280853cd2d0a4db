#include <dlfl/schemes/dual.h>

#include <optional>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/boundary_points.h>
#include <dlfl/schemes/detail/corner_origins.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/scheme_table.h>
#include <dlfl/schemes/detail/vertex_faces.h>

namespace dlfl {

Mesh dual(const Mesh& input, const BoundaryOptions& boundary, Origins* origins) {
  return detail::dual(input, boundary, origins, nullptr);
}

Mesh dual(const Mesh& input, Origins* origins) { return dual(input, BoundaryOptions{}, origins); }

Mesh detail::dual(const Mesh& input, const BoundaryOptions& boundary, Origins* origins,
                  std::vector<Origin>* corners) {
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  const auto [nv, ne, nf, nc] = dense_counts(m);

  const bool curve = boundary.rule == BoundaryRule::curve;
  std::uint32_t holes = 0;
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (!m.is_hole(FaceId(f))) continue;
    if (!curve) {
      throw TopologyError("dual: " + to_string(original_handle<FaceId>(input, f)) +
                          " is a hole: boundary=hole refuses open meshes (boundary=curve gives their dual)");
    }
    ++holes;
  }
  for (std::uint32_t e = 0; e < ne; ++e) {
    if (m.face(EdgeId(e), 0) == m.face(EdgeId(e), 1)) {
      throw TopologyError("dual: " + to_string(original_handle<EdgeId>(input, e)) +
                          " has the same face on both sides (its dual would be a self-loop)");
    }
  }

  // Output vertices: one per face that is not a hole, in face order; then, under the boundary rule, for each
  // hole corner h (in corner order) the midpoint of its edge and, at a sharp vertex, the vertex itself.
  const bool open = holes > 0;
  const std::vector<bool> sharp =
      open ? detail::sharp_boundary_vertices(m, boundary, "dual") : std::vector<bool>();
  // face_vertex[f]: the output vertex of face f (f itself on a closed mesh, where the table is left empty).
  std::vector<std::uint32_t> face_vertex(open ? nf : 0), mid(open ? nc : 0), kept(open ? nc : 0);
  std::vector<std::uint32_t> kept_vertices;
  std::uint32_t nvert = open ? 0 : nf;
  for (std::uint32_t f = 0; f < nf && open; ++f) {
    if (!m.is_hole(FaceId(f))) face_vertex[f] = nvert++;
  }
  const auto vertex_of_face = [&](std::uint32_t f) { return open ? face_vertex[f] : f; };
  const auto is_hole_corner = [&](CornerId c) { return open && m.is_hole(m.face(c)); };
  const auto is_sharp = [&](CornerId c) { return sharp[m.vertex(c).index()]; };
  if (open) {
    for (std::uint32_t k = 0; k < nc; ++k) {
      if (!is_hole_corner(CornerId(k))) continue;
      mid[k] = nvert++;
      if (is_sharp(CornerId(k))) kept_vertices.push_back(kept[k] = nvert++);
    }
  }

  // Output face v owns the corners offsets[v] .. offsets[v+1]-1: vslot[c] is the first for input corner c,
  // counter-clockwise around v, so that the dual face's normal points outward. A hole corner h takes the
  // midpoint of edge(h), then the kept vertex if any, then the midpoint of edge(prev(h)). The hole faces
  // follow, one per input hole, through hslot[h]: the kept vertex if any, then the midpoint of edge(h).
  std::vector<std::uint32_t> offsets(std::size_t(nv) + holes + 1);
  std::vector<std::uint32_t> vslot(nc), hslot(open ? nc : 0);
  detail::number_vertex_face_corners(m, input, "dual", 0, std::span(offsets).first(nv + 1), vslot, false,
                                     [&](CornerId c) -> std::uint32_t {
                                       if (!is_hole_corner(c)) return 1;
                                       return is_sharp(c) ? 3 : 2;
                                     });
  if (open) {
    std::uint32_t next_slot = offsets[nv], hole = nv;
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (!m.is_hole(FaceId(f))) continue;
      offsets[hole++] = next_slot;
      for (CornerId h : m.corners(FaceId(f))) {
        hslot[h.index()] = next_slot;
        next_slot += is_sharp(h) ? 2 : 1;
      }
    }
    offsets[hole] = next_slot;
  }
  // The dual corner of c that crosses edge(prev(c)): its last.
  const auto cross_slot = [&](CornerId c) {
    return vslot[c.index()] + (is_hole_corner(c) ? (is_sharp(c) ? 2 : 1) : 0);
  };

  MeshAssembler out(nvert, offsets);
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (m.is_hole(FaceId(f))) continue;
    glm::dvec3 sum(0.0);
    for (CornerId c : m.corners(FaceId(f))) sum += m.position(m.vertex(c));
    out.set_position(vertex_of_face(f), sum / double(m.size(FaceId(f))));
  }
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId h(k);
    if (!is_hole_corner(h)) continue;
    out.set_position(mid[k],
                     detail::boundary_midpoint(m.position(m.vertex(h)), m.position(m.vertex(m.next(h)))));
    if (is_sharp(h)) out.set_position(kept[k], m.position(m.vertex(h)));
  }

  // Twins. The dual corner of c (at v, in face f) runs from dual vertex f to dual vertex face(d), d =
  // opposite(prev(c)), p = prev(c): it crosses the input edge g = edge(p), which runs from w = vertex(p) to
  // v. Its twin is the dual corner in face w that crosses g from face(d) back to f: the corner c' at w in
  // face(d) whose prev has edge g, i.e. prev(c') = d, c' = next(d) = next(opposite(prev(c))). (Applying the
  // rule to c' gives next(opposite(d)) = next(p) = c back.) Under the boundary rule a hole's group of corners
  // lands and leaves at the midpoints of the hole's edges, so the same pairing holds for its last corner, and
  // its sides along the boundary (midpoint of edge(h), kept vertex, midpoint of edge(prev(h))) pair with the
  // hole face's, which runs the other way: kept vertex of h, midpoint of edge(h), kept vertex of next(h), ...
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const std::uint32_t cross = cross_slot(c);
    const std::uint32_t from = is_hole_corner(c) ? mid[m.prev(c).index()] : vertex_of_face(m.face(c).index());
    out.set_corner(cross, from, cross_slot(m.next(m.opposite(m.prev(c)))));
    if (!is_hole_corner(c)) continue;
    const std::uint32_t before = hslot[m.prev(c).index()] + (is_sharp(m.prev(c)) ? 1 : 0);  // its midpoint
    if (is_sharp(c)) {
      out.set_corner(vslot[k], mid[k], hslot[k]);
      out.set_corner(vslot[k] + 1, kept[k], before);
      out.set_corner(hslot[k], kept[k], vslot[k]);
      out.set_corner(before, mid[m.prev(c).index()], vslot[k] + 1);
    } else {
      out.set_corner(vslot[k], mid[k], before);
      out.set_corner(before, mid[m.prev(c).index()], vslot[k]);
    }
  }
  for (std::uint32_t hole = 0; hole < holes; ++hole) out.set_hole(nv + hole, true);
  Mesh result = out.finish();
  detail::mark_sharp(result, kept_vertices);
  if (origins || corners) {
    const detail::InputHandles in(input);
    if (corners) {
      corners->assign(result.num_corners(), Origin{});
      for (std::uint32_t k = 0; k < nc; ++k) {
        const std::uint32_t count = is_hole_corner(CornerId(k)) ? (is_sharp(CornerId(k)) ? 3 : 2) : 1;
        for (std::uint32_t i = 0; i < count; ++i) (*corners)[vslot[k] + i] = in.corner(k);
        if (!is_hole_corner(CornerId(k))) continue;
        for (std::uint32_t i = 0; i < count - 1; ++i) (*corners)[hslot[k] + i] = in.corner(k);
      }
    }
    if (origins) {
      detail::reset_origins(*origins, result);
      for (std::uint32_t f = 0; f < nf; ++f) {
        if (!m.is_hole(FaceId(f))) origins->vertices[vertex_of_face(f)] = in.face(f);
      }
      for (std::uint32_t v = 0; v < nv; ++v) origins->faces[v] = in.vertex(v);
      std::uint32_t hole = nv;
      for (std::uint32_t f = 0; f < nf; ++f) {
        if (m.is_hole(FaceId(f))) origins->faces[hole++] = in.face(f);
      }
      // The corner for c crosses edge(prev(c)) (see the twins above); the boundary sides of a hole corner's
      // group stand for its vertex, and so do the hole face's sides that pair with them.
      std::vector<Origin> edge_of(result.num_corners());
      for (std::uint32_t k = 0; k < nc; ++k) {
        const CornerId c(k);
        edge_of[cross_slot(c)] = in.edge(m.edge(m.prev(c)).index());
        if (!is_hole_corner(c)) continue;
        origins->vertices[mid[k]] = in.edge(m.edge(c).index());
        if (is_sharp(c)) origins->vertices[kept[k]] = in.vertex(m.vertex(c).index());
        const Origin vertex = in.vertex(m.vertex(c).index());
        edge_of[vslot[k]] = vertex;
        if (is_sharp(c)) edge_of[vslot[k] + 1] = edge_of[hslot[k]] = vertex;
        edge_of[hslot[m.prev(c).index()] + (is_sharp(m.prev(c)) ? 1 : 0)] = vertex;
      }
      detail::set_edge_origins(*origins, result, edge_of);
    }
  }
  return result;
}

namespace detail {

SchemeSpec dual_scheme() {
  return boundary_scheme(
      dlfl::dual, "dual",
      "the dual mesh: a vertex per face (at its centroid), a face per vertex, an edge across every edge",
      [](const MeshCounts& c) {
        return MeshCounts{c.faces, c.edges, c.vertices};
      });
}

}  // namespace detail
}  // namespace dlfl

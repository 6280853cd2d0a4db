#include <dlfl/schemes/mlca_polygons.h>

#include <optional>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/quad_split.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {
namespace {

void refuse_point_spheres(const Mesh& m, const char* scheme) {
  for (VertexId v : m.vertices()) {
    if (m.is_point_sphere(v))
      throw TopologyError(std::string(scheme) + ": " + to_string(v) + " is a point sphere");
  }
}

Mesh split_dense(const Mesh& m) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  MeshAssembler out(std::size_t(nv) + ne + nf, m.num_corners(), 4);
  for (std::uint32_t v = 0; v < nv; ++v) out.set_position(v, m.position(VertexId(v)));
  for (std::uint32_t e = 0; e < ne; ++e) {
    out.set_position(nv + e, 0.5 * (m.position(m.from(EdgeId(e))) + m.position(m.to(EdgeId(e)))));
  }
  for (std::uint32_t f = 0; f < nf; ++f) {
    glm::dvec3 sum(0.0);
    for (CornerId c : m.corners(FaceId(f))) sum += m.position(m.vertex(c));
    out.set_position(nv + ne + f, sum / double(m.size(FaceId(f))));
  }
  detail::assemble_quad_split(m, out);
  return out.finish();
}

// Bilinear subdivision and cell averaging in one pass over the coarse mesh, whose non-hole faces are quads.
// The fine quad of corner c has the centroid Q = (p_v + m_out + F + m_in) / 4 = (2 p_v + (p_next + p_prev)/2
// + F) / 4; a fine vertex is the average of the Q of the fine quads around it. Face points come out at their
// face's centroid (the average over the face of Q is F), so only vertex and edge points need sums.
Mesh mlca_quad_step(const Mesh& m) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  const std::uint32_t edge_base = nv, face_base = nv + ne;
  MeshAssembler out(std::size_t(nv) + ne + nf, m.num_corners(), 4);

  // One pass over the faces: the face point, and the sums of fine quad centroids for vertex points (at
  // 0..nv-1) and edge points (at nv..nv+ne-1). The fine quads of corners c_i and c_{i+1} are the two of this
  // face at the edge from c_i to c_{i+1}. Hole quads are not cells of the surface and add nothing.
  detail::LargeVector<glm::dvec3> sums(std::size_t(nv) + ne, glm::dvec3(0.0));
  detail::LargeVector<std::uint32_t> quads_at(nv, 0);
  bool any_hole = false;
  for (std::uint32_t f = 0; f < nf; ++f) {
    const FaceId face(f);
    if (m.is_hole(face)) {
      any_hole = true;
      glm::dvec3 sum(0.0);
      for (CornerId c : m.corners(face)) sum += m.position(m.vertex(c));
      out.set_position(face_base + f, sum / double(m.size(face)));
      continue;
    }
    CornerId c[4];
    c[0] = m.first_corner(face);
    for (int i = 1; i < 4; ++i) c[i] = m.next(c[i - 1]);
    std::uint32_t v[4];
    glm::dvec3 p[4];
    for (int i = 0; i < 4; ++i) {
      v[i] = m.vertex(c[i]).index();
      p[i] = m.position(VertexId(v[i]));
    }
    const glm::dvec3 centre = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    out.set_position(face_base + f, centre);
    glm::dvec3 q[4];
    for (int i = 0; i < 4; ++i) q[i] = 0.5 * p[i] + 0.125 * (p[(i + 1) & 3] + p[(i + 3) & 3]) + 0.25 * centre;
    for (int i = 0; i < 4; ++i) {
      sums[v[i]] += q[i];
      ++quads_at[v[i]];
      sums[edge_base + m.edge(c[i]).index()] += q[i] + q[(i + 1) & 3];
    }
  }
  // Boundary edges are crease segments: a vertex on one averages over the fine segments (p_v + m) / 2 around
  // it, which is 3/4 p_v + 1/(4k) of its k boundary neighbours; the edge point itself stays at the midpoint.
  detail::LargeVector<glm::dvec3> crease_sum;
  detail::LargeVector<std::uint32_t> crease_count;
  if (any_hole) {
    crease_sum.assign(nv, glm::dvec3(0.0));
    crease_count.assign(nv, 0);
  }
  for (std::uint32_t e = 0; e < ne; ++e) {
    const EdgeId id(e);
    const std::uint32_t a = m.from(id).index(), b = m.to(id).index();
    const glm::dvec3 pa = m.position(VertexId(a)), pb = m.position(VertexId(b));
    const bool hole0 = any_hole && m.is_hole(m.face(id, 0));
    const bool hole1 = any_hole && m.is_hole(m.face(id, 1));
    if (!hole0 && !hole1) {
      out.set_position(edge_base + e, 0.25 * sums[edge_base + e]);
      continue;
    }
    out.set_position(edge_base + e, 0.5 * (pa + pb));
    if (hole0 != hole1) {
      crease_sum[a] += pb;
      crease_sum[b] += pa;
      ++crease_count[a];
      ++crease_count[b];
    }
  }
  for (std::uint32_t v = 0; v < nv; ++v) {
    const glm::dvec3& p = m.position(VertexId(v));
    if (any_hole && crease_count[v] > 0) {
      out.set_position(v, 0.75 * p + crease_sum[v] / (4.0 * crease_count[v]));
    } else if (quads_at[v] > 0) {
      out.set_position(v, sums[v] / double(quads_at[v]));
    } else {
      out.set_position(v, p);  // only holes around: no cell to average over
    }
  }
  detail::assemble_quad_split(m, out);
  return out.finish();
}

Mesh mlca_without_point_spheres(const Mesh& input, Origins* origins) {
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);
  bool quads = true;
  for (FaceId f : m.faces()) {
    if (!m.is_hole(f) && m.size(f) != 4) {
      quads = false;
      break;
    }
  }
  if (quads) {
    Mesh result = mlca_quad_step(m);
    if (origins) detail::quad_split_origins(m, result, detail::InputHandles(input), *origins);
    return result;
  }
  const Mesh split = split_dense(m);
  Mesh result = mlca_quad_step(split);
  if (origins) {
    // The step's origins name the split's elements; the split's own origins take them back to the input.
    const detail::InputHandles in(input);
    Origins split_origins;
    detail::quad_split_origins(m, split, in, split_origins);
    detail::quad_split_origins(split, result, detail::InputHandles(split), *origins);
    detail::compose(*origins, split_origins, detail::quad_split_corner_origins(m, in));
  }
  return result;
}

}  // namespace

Mesh split_to_quads(const Mesh& input) {
  refuse_point_spheres(input, "split_to_quads");
  std::optional<Mesh> storage;
  return split_dense(dense_mesh(input, storage));
}

Mesh mlca(const Mesh& input, Origins* origins) {
  std::vector<VertexId> point_spheres;
  for (VertexId v : input.vertices()) {
    if (input.is_point_sphere(v)) point_spheres.push_back(v);
  }
  if (point_spheres.empty()) return mlca_without_point_spheres(input, origins);
  // Rare: take the point spheres out, subdivide the rest, and put them back unchanged (0-cells). The
  // stripped copy keeps the input's handles, so its origins are the input's.
  Mesh stripped = input;
  for (VertexId v : point_spheres) stripped.delete_vertex(v);
  Mesh out = stripped.empty() ? Mesh() : mlca_without_point_spheres(stripped, origins);
  if (origins && stripped.empty()) *origins = Origins{};
  for (VertexId v : point_spheres) {
    const VertexId copy = out.create_vertex(input.position(v));
    if (!origins) continue;
    origins->vertices.resize(out.vertex_capacity());
    origins->faces.resize(out.face_capacity());
    origins->vertices[copy.index()] = origin_of(v);
    origins->faces[out.face(out.corner(copy)).index()] = origin_of(v);
  }
  return out;
}

namespace detail {

SchemeSpec mlca_scheme() {
  return parameterless_scheme(
      mlca, "mlca",
      "MLCA (multi-linear subdivision, cell averaging) on polygon meshes: quads, split first if needed",
      [](const MeshCounts& c) {  // the quad split: V' = V + E + F, F' = C = 2E, so E' = 4E by Euler
        return MeshCounts{c.vertices + c.edges + c.faces, 4 * c.edges, 2 * c.edges};
      });
}

}  // namespace detail
}  // namespace dlfl

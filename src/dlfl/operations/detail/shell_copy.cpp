// The mirrored copy. A mesh is its rotation system (the cyclic order of the edges around each vertex, whose
// orbits are the faces), and insert_edge(c1, c2) puts the new edge into the angles of c1 and c2, just before
// their outgoing edges in the turn around their vertices. So inserting the copy's edges in any order, each
// just before the edge that follows it in the mirrored rotation among the copy's edges present at that time,
// builds the mirror image (as reverse_orientation rebuilds one); the order only decides the cost. Which
// present edge that is follows from taking the edges out of per-vertex rotation lists in the reverse order,
// O(1) each.

#include <dlfl/operations/detail/edge_ends.h>
#include <dlfl/operations/detail/shell_copy.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include <dlfl/format.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/connect_faces.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl::detail {
namespace {

constexpr std::uint32_t none = no_edge_end;

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The order in which the copy's edges go in: a spanning forest of the vertices (breadth first, so that each
// edge brings in a point sphere), then the edges left over by a spanning forest of the faces (they close the
// handles), then that forest's edges, later-discovered faces first (children before their parents), so that
// each closes exactly one face.
}  // namespace

std::vector<EdgeId> edge_build_order(const Mesh& m) {
  std::vector<char> in_forest(m.edge_capacity(), 0);
  std::vector<EdgeId> tree, cotree, rest;
  tree.reserve(m.num_vertices());
  std::vector<char> seen(m.vertex_capacity(), 0);
  std::vector<VertexId> queue;
  for (VertexId root : m.vertices()) {
    if (seen[root.index()] || m.is_point_sphere(root)) continue;
    seen[root.index()] = 1;
    queue.assign(1, root);
    for (std::size_t i = 0; i < queue.size(); ++i) {
      for (CornerId c : m.corners(queue[i])) {
        const VertexId w = m.vertex(m.next(c));
        if (seen[w.index()]) continue;
        seen[w.index()] = 1;
        in_forest[m.edge(c).index()] = 1;
        tree.push_back(m.edge(c));
        queue.push_back(w);
      }
    }
  }
  std::vector<char> face_seen(m.face_capacity(), 0);
  std::vector<FaceId> faces;
  for (FaceId root : m.faces()) {
    if (face_seen[root.index()] || !m.edge(m.first_corner(root)).valid()) continue;
    face_seen[root.index()] = 1;
    faces.assign(1, root);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      for (CornerId c : m.corners(faces[i])) {
        const EdgeId e = m.edge(c);
        const FaceId g = m.face(m.opposite(c));
        if (in_forest[e.index()] || face_seen[g.index()]) continue;
        face_seen[g.index()] = 1;
        in_forest[e.index()] = 2;
        cotree.push_back(e);
        faces.push_back(g);
      }
    }
  }
  for (EdgeId e : m.edges()) {
    if (!in_forest[e.index()]) rest.push_back(e);
  }
  std::vector<EdgeId> order = std::move(tree);
  order.reserve(m.num_edges());
  order.insert(order.end(), rest.begin(), rest.end());
  order.insert(order.end(), cotree.rbegin(), cotree.rend());
  return order;
}

void remove_surface(Transaction& tx) {
  const Mesh& m = tx.mesh();
  const std::vector<EdgeId> order = edge_build_order(m);
  std::vector<VertexId> with_edges;
  for (VertexId v : m.vertices()) {
    if (!m.is_point_sphere(v)) with_edges.push_back(v);
  }
  for (auto e = order.rbegin(); e != order.rend(); ++e) tx.delete_edge(*e);
  for (VertexId v : with_edges) tx.delete_vertex(v);
}

namespace {

// For each edge of `order` and each of its sides: the edge end that turns just before it around that vertex
// in the original (just after it in the mirror image) among the edges inserted before it, or `none`.
std::vector<std::uint32_t> mirror_neighbours(const Mesh& m, const std::vector<EdgeId>& order) {
  const std::size_t ends = 2 * std::size_t(m.edge_capacity());
  std::vector<std::uint32_t> turn_next(ends, none), turn_prev(ends, none);
  for (CornerId c : m.corners()) {
    if (!m.edge(c).valid()) continue;
    const std::uint32_t from = end_of(m, c), to = end_of(m, m.next_around_vertex(c));
    turn_next[from] = to;
    turn_prev[to] = from;
  }
  std::vector<std::uint32_t> before(2 * order.size(), none);
  for (std::size_t i = order.size(); i-- > 0;) {
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t end = 2 * order[i].index() + side;
      const std::uint32_t prev = turn_prev[end], next = turn_next[end];
      if (prev == end) continue;  // the vertex's only edge at that point
      before[2 * i + side] = prev;
      turn_next[prev] = next;
      turn_prev[next] = prev;
    }
  }
  return before;
}

}  // namespace

CornerId MirroredCopy::twin(const Mesh& mesh, CornerId c) const {
  // In the reversed face the corner at v leaves along the edge that arrives at v in the original.
  return corner_at(mesh, edges[mesh.edge(mesh.prev(c)).index()], vertices[mesh.vertex(c).index()]);
}

MirroredCopy add_mirrored_copy(Transaction& tx, std::span<const glm::dvec3> positions,
                               bool copy_point_spheres) {
  const Mesh& m = tx.mesh();
  const std::vector<EdgeId> order = edge_build_order(m);
  const std::vector<std::uint32_t> before = mirror_neighbours(m, order);
  const std::vector<FaceId> holes = [&] {
    std::vector<FaceId> out;
    for (FaceId f : m.faces()) {
      if (m.is_hole(f) && (copy_point_spheres || m.edge(m.first_corner(f)).valid())) out.push_back(f);
    }
    return out;
  }();
  MirroredCopy copy;
  copy.vertices.assign(m.vertex_capacity(), VertexId());
  copy.edges.assign(m.edge_capacity(), EdgeId());
  const std::uint32_t vertex_capacity = m.vertex_capacity();
  for (std::uint32_t i = 0; i < vertex_capacity; ++i) {
    const VertexId v(i);
    if (!m.is_alive(v) || (!copy_point_spheres && m.is_point_sphere(v))) continue;
    copy.vertices[i] = tx.create_vertex(positions[i]);
  }
  // Per edge end 2e + side: the copy of its vertex until e's copy is in, then the copy's corner there (the
  // copy's side s runs from the copy of the original's side-s vertex, and insert_edge never moves an edge's
  // corners). So each end is looked up in one array, in the order of the build, rather than through the
  // edge, its corner and the vertex's copy (three scattered reads a side at a million faces).
  std::vector<std::uint32_t> end_at(2 * std::size_t(m.edge_capacity()), none);
  for (EdgeId e : m.edges()) {
    for (int side = 0; side < 2; ++side) {
      end_at[2 * e.index() + side] = copy.vertices[m.vertex(m.corner(e, side)).index()].index();
    }
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::uint32_t e = order[i].index();
    CornerId at[2];
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t b = before[2 * i + side];
      at[side] = b == none ? m.corner(VertexId(end_at[2 * e + side])) : CornerId(end_at[b]);
    }
    const EdgeId made = tx.insert_edge(at[0], at[1]).edge;
    copy.edges[e] = made;
    end_at[2 * e] = m.corner(made, 0).index();
    end_at[2 * e + 1] = m.corner(made, 1).index();
  }
  for (FaceId f : holes) {
    const FaceId twin = m.edge(m.first_corner(f)).valid()
                            ? copy.twin(m, f)
                            : m.face(m.corner(copy.vertices[m.vertex(m.first_corner(f)).index()]));
    tx.set_hole(twin, true);
  }
  return copy;
}

std::vector<glm::dvec3> inner_positions(const Mesh& mesh, std::string_view op, std::string_view param,
                                        double thickness) {
  if (!std::isfinite(thickness) || !(thickness > 0.0)) {
    refuse_worded(op, param, " = " + format_number(thickness) + " must be finite and > 0");
  }
  std::vector<glm::dvec3> newell(mesh.face_capacity(), glm::dvec3(0.0));
  for (FaceId f : mesh.faces()) {
    if (!mesh.is_hole(f)) newell[f.index()] = newell_vector(mesh, f);
  }
  std::vector<glm::dvec3> out(mesh.vertex_capacity(), glm::dvec3(0.0));
  for (VertexId v : mesh.vertices()) {
    // As vertex_normal, with each face's Newell vector computed once (the same sums in the same order).
    glm::dvec3 sum(0.0);
    for (CornerId c : mesh.corners(v)) {
      if (!mesh.is_hole(mesh.face(c))) sum += newell[mesh.face(c).index()];
    }
    const double length = glm::length(sum);
    const glm::dvec3 normal = length > 0.0 ? sum / length : glm::dvec3(0.0);
    out[v.index()] = mesh.position(v) - thickness * normal;
    if (!finite(out[v.index()])) {
      refuse(op, param, "the inner copy of " + to_string(v) + " would not have a finite position");
    }
  }
  return out;
}

void punch(Transaction& tx, const MirroredCopy& copy, FaceId f) {
  const Mesh& m = tx.mesh();
  ConnectFacesOptions options;
  options.corner1 = m.first_corner(f);
  options.corner2 = copy.twin(m, options.corner1);
  connect_faces(tx, f, m.face(options.corner2), options);
}

MirroredCopy add_shell(Transaction& tx, std::span<const glm::dvec3> inner, std::span<const FaceId> punched,
                       bool copy_point_spheres) {
  const Mesh& m = tx.mesh();
  std::vector<FaceId> tubes(punched.begin(), punched.end());
  for (FaceId f : m.faces()) {
    if (m.is_hole(f) && m.edge(m.first_corner(f)).valid()) tubes.push_back(f);
  }
  MirroredCopy copy = add_mirrored_copy(tx, inner, copy_point_spheres);
  // A tube changes only its two faces, so the twins found now stay right for the tubes after it.
  for (FaceId f : tubes) punch(tx, copy, f);
  return copy;
}

}  // namespace dlfl::detail

#include <dlfl/schemes/detail/honeycomb_remesh.h>

#include <algorithm>

#include <dlfl/create_face_manifold.h>
#include <dlfl/schemes/detail/boundary_points.h>

namespace dlfl::detail {

HoneycombRemesh honeycomb_remesh(const Mesh& mesh, const FacePointsFn& face_points, bool want_face_of_vertex,
                                 const BoundaryOptions& boundary, const char* scheme, Origins* origins) {
  // The origins of faces around vertices and of front edges need the front corners.
  want_face_of_vertex = want_face_of_vertex || origins;
  const bool curve = boundary.rule == BoundaryRule::curve && has_hole(mesh);
  // Corners and faces of 2 or more corners, point spheres, and the corners of holes under the boundary rule.
  std::size_t C = 0, F = 0, P = 0, H = 0;
  std::uint32_t max_n = 0;
  for (FaceId f : mesh.faces()) {
    const std::uint32_t n = mesh.size(f);
    if (n == 1) {
      ++P;
      continue;
    }
    ++F;
    C += n;
    if (curve && mesh.is_hole(f)) H += n;
    max_n = std::max(max_n, n);
  }
  const std::vector<bool> sharp =
      curve ? sharp_boundary_vertices(mesh, boundary, scheme) : std::vector<bool>();
  const auto marks = curve ? sharp_marks(mesh, scheme) : std::nullopt;
  // Exact final capacities, tombstones included. CREATEFACEMANIFOLD of N points appends N vertices, N edges,
  // 2N corners (N from create_vertex, none for the first insert_edge between two point spheres, one for each
  // of the next N - 2, two for the closing one) and N + 1 faces (N point spheres, N - 1 of them merged away,
  // plus the one the closing split creates). Step 2 appends per edge 2 corners, 1 edge, and 1 face if it
  // splits. From 2F faces the merges and splits end at F + V, so splits - merges = V - F and
  // splits + merges = E. A hole's manifold under the boundary rule has 2N points: N more of each but corners
  // (2N more).
  const std::size_t E = mesh.num_edges();
  const std::size_t V = mesh.num_vertices() - std::min(P, mesh.num_vertices());
  const std::size_t splits = E + V >= F ? (E + V - F) / 2 : 0;
  HoneycombRemesh out;
  Mesh& result = out.mesh;
  result.reserve(C + P + H, C + E + H, C + F + splits + P + H, 2 * C + 2 * E + P + 2 * H);
  out.face_of_face.assign(mesh.face_capacity(), FaceId());
  if (want_face_of_vertex) out.face_of_vertex.assign(mesh.vertex_capacity(), FaceId());

  // Old corner -> back corner of the new vertex made for it; and, when the vertex faces are wanted, -> its
  // front corner.
  std::vector<CornerId> back_of(mesh.corner_capacity());
  std::vector<CornerId> front_of(want_face_of_vertex ? mesh.corner_capacity() : 0);
  const std::size_t max_points = curve ? 2 * std::size_t(max_n) : max_n;
  std::vector<glm::dvec3> points(max_points);
  std::vector<CornerId> old_corners(max_n), back_corners(max_points), front_corners(max_points);
  // Under the boundary rule: each boundary vertex point, with the hole corner it is made for and its front
  // corner (for the origins and the marks).
  struct VertexPoint {
    CornerId hole_corner;
    CornerId front;
  };
  std::vector<VertexPoint> vertex_points;
  if (curve) vertex_points.reserve(H);

  // Step 1: a face manifold per face.
  for (FaceId f : mesh.faces()) {
    const std::uint32_t N = mesh.size(f);
    if (N == 1) {
      const VertexId v = mesh.vertex(mesh.first_corner(f));
      const VertexId copy = result.create_vertex(mesh.position(v));
      if (want_face_of_vertex) out.face_of_vertex[v.index()] = result.face(result.corner(copy));
      continue;
    }
    std::uint32_t i = 0;
    for (CornerId c : mesh.corners(f)) old_corners[i++] = c;
    // The boundary rule interleaves the vertex points: point 2i is v_i's, point 2i + 1 the one made for h_i.
    const bool boundary_loop = curve && mesh.is_hole(f);
    const std::uint32_t M = boundary_loop ? 2 * N : N, stride = boundary_loop ? 2 : 1;
    if (boundary_loop) {
      for (i = 0; i < N; ++i) {
        const CornerId h = old_corners[i];
        const VertexId u = mesh.vertex(mesh.prev(h)), v = mesh.vertex(h), w = mesh.vertex(mesh.next(h));
        points[2 * i] =
            honeycomb_boundary_vertex(mesh.position(u), mesh.position(v), mesh.position(w), sharp[v.index()]);
        points[2 * i + 1] = boundary_midpoint(mesh.position(v), mesh.position(w));
      }
    } else {
      face_points(f, std::span<const CornerId>(old_corners.data(), N),
                  std::span<glm::dvec3>(points.data(), N));
    }
    const bool want_front = want_face_of_vertex || boundary_loop;
    const FaceManifold fm = create_face_manifold(
        result, std::span<const glm::dvec3>(points.data(), M), {},
        want_front ? std::span<CornerId>(front_corners.data(), M) : std::span<CornerId>(),
        std::span<CornerId>(back_corners.data(), M));
    if (mesh.is_hole(f)) result.set_hole(fm.front, true);
    out.face_of_face[f.index()] = fm.front;
    const std::uint32_t first = stride - 1;
    for (i = 0; i < N; ++i) back_of[old_corners[i].index()] = back_corners[stride * i + first];
    if (want_face_of_vertex) {
      for (i = 0; i < N; ++i) front_of[old_corners[i].index()] = front_corners[stride * i + first];
    }
    if (boundary_loop) {
      for (i = 0; i < N; ++i) vertex_points.push_back({old_corners[i], front_corners[2 * i]});
    }
  }

  // Step 2: join the two new vertices of each edge, across the edge, through their back corners. Each back
  // corner keeps its vertex and outgoing edge through every insert_edge, so the map stays valid.
  std::vector<EdgeId> edge_across;  // by new edge handle: the input edge it crosses, when origins are wanted
  if (origins) edge_across.assign(result.edge_capacity() + mesh.num_edges(), EdgeId());
  for (EdgeId e : mesh.edges()) {
    const InsertEdgeResult r =
        result.insert_edge(back_of[mesh.corner(e, 0).index()], back_of[mesh.corner(e, 1).index()]);
    if (origins) edge_across[r.edge.index()] = e;
  }

  // The front face's side from the point of corner c to the point of next(c) joins two points next to the old
  // vertex of next(c) (both on edges at it), so the face across that side is that vertex's face.
  if (want_face_of_vertex) {
    for (CornerId c : mesh.corners()) {
      if (!mesh.edge(c).valid()) continue;  // a point sphere's corner
      out.face_of_vertex[mesh.vertex(mesh.next(c)).index()] =
          result.face(result.opposite(front_of[c.index()]));
    }
  }
  if (origins) {
    origins->vertices.assign(result.vertex_capacity(), Origin{});
    origins->edges.assign(result.edge_capacity(), Origin{});
    origins->faces.assign(result.face_capacity(), Origin{});
    for (CornerId c : mesh.corners()) {
      if (!mesh.edge(c).valid()) continue;  // a point sphere's corner
      origins->vertices[result.vertex(back_of[c.index()]).index()] = origin_of(c);
      origins->edges[result.edge(front_of[c.index()]).index()] = origin_of(mesh.next(c));
    }
    for (std::uint32_t e = 0; e < edge_across.size(); ++e) {
      if (edge_across[e].valid()) origins->edges[e] = origin_of(edge_across[e]);
    }
    for (FaceId f : mesh.faces()) {
      if (out.face_of_face[f.index()].valid())
        origins->faces[out.face_of_face[f.index()].index()] = origin_of(f);
    }
    for (VertexId v : mesh.vertices()) {
      const FaceId around = out.face_of_vertex[v.index()];
      origins->faces[around.index()] = origin_of(v);
      // A point sphere's copy (its vertex is not made for a corner).
      if (mesh.is_point_sphere(v))
        origins->vertices[result.vertex(result.first_corner(around)).index()] = origin_of(v);
    }
    for (const VertexPoint& p : vertex_points) {
      origins->vertices[result.vertex(p.front).index()] = origin_of(mesh.vertex(p.hole_corner));
      origins->edges[result.edge(p.front).index()] = origin_of(p.hole_corner);
    }
  }
  if (marks) {
    std::vector<std::uint32_t> marked;
    for (const VertexPoint& p : vertex_points) {
      if ((*marks)[mesh.vertex(p.hole_corner)]) marked.push_back(result.vertex(p.front).index());
    }
    mark_sharp(result, marked);
  }
  return out;
}

}  // namespace dlfl::detail

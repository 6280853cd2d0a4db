#include <dlfl/mesh.h>

#include <cmath>
#include <cstring>

#include <dlfl/errors.h>

namespace dlfl {
namespace {
bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

template <class H>
std::string missing_message(const char* op, H h) {
  return std::string(op) + ": " + to_string(h) + " does not exist (removed or never created)";
}
}  // namespace

void Mesh::reserve(std::size_t vertices, std::size_t edges, std::size_t faces, std::size_t corners) {
  positions_.reserve(vertices);
  vertex_corner_.reserve(vertices);
  edges_.reserve(edges);
  faces_.reserve(faces);
  corners_.reserve(corners);
}

std::uint32_t Mesh::valence(VertexId v) const {
  if (is_point_sphere(v)) return 0;
  std::uint32_t n = 0;
  for ([[maybe_unused]] CornerId c : corners(v)) ++n;
  return n;
}

void Mesh::missing(VertexId v, const char* op) { throw InvalidArgument(missing_message(op, v)); }
void Mesh::missing(EdgeId e, const char* op) { throw InvalidArgument(missing_message(op, e)); }
void Mesh::missing(FaceId f, const char* op) { throw InvalidArgument(missing_message(op, f)); }
void Mesh::missing(CornerId c, const char* op) { throw InvalidArgument(missing_message(op, c)); }

void Mesh::set_anchors(const Reuse& reuse) {
  // Anchors that no longer fit (the element is gone, or the corner is elsewhere) are ignored: they only
  // choose where iteration starts, never the topology.
  for (const auto& a : reuse.face_anchors) {
    if (is_alive(a.face) && is_alive(a.corner) && face(a.corner) == a.face)
      faces_[a.face.index()].corner = a.corner;
  }
  for (const auto& a : reuse.vertex_anchors) {
    if (is_alive(a.vertex) && is_alive(a.corner) && vertex(a.corner) == a.vertex) {
      vertex_corner_[a.vertex.index()] = a.corner;
    }
  }
}

void Mesh::relabel(CornerId start, FaceId f) {
  CornerId c = start;
  do {
    corners_[c.index()].face = f;
    c = next(c);
  } while (c != start);
}

// ---- simple mutators
// ---------------------------------------------------------------------------------------

void Mesh::set_position(VertexId v, const glm::dvec3& position) {
  require(v, "set_position");
  if (!finite(position))
    throw InvalidArgument("set_position: position of " + to_string(v) + " is not finite");
  positions_[v.index()] = position;
}

void Mesh::set_first_corner(FaceId f, CornerId c) {
  require(f, "set_first_corner");
  require(c, "set_first_corner");
  if (face(c) != f)
    throw InvalidArgument("set_first_corner: " + to_string(c) + " is not a corner of " + to_string(f));
  faces_[f.index()].corner = c;
}

void Mesh::set_vertex_corner(VertexId v, CornerId c) {
  require(v, "set_vertex_corner");
  require(c, "set_vertex_corner");
  if (vertex(c) != v) {
    throw InvalidArgument("set_vertex_corner: " + to_string(c) + " is not a corner of " + to_string(v));
  }
  vertex_corner_[v.index()] = c;
}

glm::dvec3 Mesh::face_point_or_centroid(FaceId f) const {
  if (auto p = face_point(f)) return *p;
  glm::dvec3 sum(0.0);
  for (CornerId c : corners(f)) sum += position(vertex(c));
  return sum / double(size(f));
}

void Mesh::set_face_point(FaceId f, const std::optional<glm::dvec3>& point) {
  require(f, "set_face_point");
  if (point && !finite(*point)) {
    throw InvalidArgument("set_face_point: control point of " + to_string(f) + " is not finite");
  }
  if (face_points_.empty()) {
    if (!point) return;
    face_points_.assign(faces_.size(), glm::dvec3(std::nan(""), 0.0, 0.0));
  }
  face_points_[f.index()] = point ? *point : glm::dvec3(std::nan(""), 0.0, 0.0);
}

void Mesh::set_hole(FaceId f, bool hole) {
  require(f, "set_hole");
  faces_[f.index()].hole = hole;
}

// ---- CREATEVERTEX and its inverse
// --------------------------------------------------------------------------

VertexId Mesh::create_vertex(const glm::dvec3& position, const Reuse& reuse) {
  if (!finite(position)) throw InvalidArgument("create_vertex: position is not finite");
  if ((reuse.vertex.valid() && (reuse.vertex.index() >= vertex_capacity() || is_alive(reuse.vertex))) ||
      (reuse.face.valid() && (reuse.face.index() >= face_capacity() || is_alive(reuse.face))) ||
      (reuse.corners[0].valid() &&
       (reuse.corners[0].index() >= corner_capacity() || is_alive(reuse.corners[0])))) {
    throw InvalidArgument("create_vertex: a handle to reuse is not a removed element");
  }
  VertexId v = new_vertex(reuse.vertex);
  FaceId f = new_face(reuse.face);
  CornerId c = new_corner(reuse.corners[0]);
  positions_[v.index()] = position;
  vertex_corner_[v.index()] = c;
  corners_[c.index()] = {v, f, c, c, EdgeId()};
  faces_[f.index()].corner = c;
  faces_[f.index()].size = 1;
  if (!reuse.face.valid()) faces_[f.index()].hole = false;
  apply_anchors(reuse);
  return v;
}

void Mesh::delete_vertex(VertexId v, const Reuse& reuse) {
  require(v, "delete_vertex");
  if (!is_point_sphere(v)) {
    throw TopologyError("delete_vertex: " + to_string(v) + " has edges; only a point sphere can be deleted");
  }
  CornerId c = corner(v);
  kill(face(c));
  kill(c);
  kill(v);
  apply_anchors(reuse);
}

// ---- dispatch
// ----------------------------------------------------------------------------------------------

Step Mesh::apply(const Step& step) {
  Step inverse;
  switch (step.kind) {
    case Step::Kind::create_vertex: {
      VertexId v = create_vertex(step.position, step.reuse);
      inverse.kind = Step::Kind::delete_vertex;
      inverse.vertex = v;
      return inverse;
    }
    case Step::Kind::delete_vertex: {
      require(step.vertex, "delete_vertex");
      CornerId c = corner(step.vertex);
      inverse.kind = Step::Kind::create_vertex;
      inverse.position = position(step.vertex);
      inverse.reuse.vertex = step.vertex;
      inverse.reuse.face = is_alive(c) ? face(c) : FaceId();
      inverse.reuse.corners[0] = c;
      inverse.reuse.face_anchors[0] = {inverse.reuse.face, c};
      delete_vertex(step.vertex, step.reuse);
      return inverse;
    }
    case Step::Kind::insert_edge:
      return insert_edge(step.corner1, step.corner2, step.reuse).inverse;
    case Step::Kind::delete_edge:
      return delete_edge(step.edge, step.reuse).inverse;
    case Step::Kind::subdivide_edge: {
      VertexId v = subdivide_edge(step.edge, step.position, step.reuse);
      inverse.kind = Step::Kind::unsubdivide_edge;
      inverse.vertex = v;
      return inverse;
    }
    case Step::Kind::unsubdivide_edge: {
      require(step.vertex, "unsubdivide_edge");
      // Record what subdivide_edge needs to rebuild exactly this vertex (checked again by unsubdivide_edge).
      CornerId a = corner(step.vertex);
      CornerId b = is_point_sphere(step.vertex) ? a : next_around_vertex(a);
      // The corner at v whose edge leaves v on side 0 is the one subdivide_edge appends first.
      EdgeId ea = edge(a);
      bool a_leaves = ea.valid() && corner(ea, 0) == a;
      CornerId leaving = a_leaves ? a : b;
      CornerId arriving = a_leaves ? b : a;
      inverse.kind = Step::Kind::subdivide_edge;
      inverse.position = position(step.vertex);
      inverse.reuse.vertex = step.vertex;
      inverse.reuse.corners = {leaving, arriving};
      if (is_alive(arriving) && edge(arriving).valid()) inverse.edge = edge(arriving);
      if (is_alive(leaving) && edge(leaving).valid()) inverse.reuse.edge = edge(leaving);
      inverse.reuse.vertex_anchors[0] = {step.vertex, a};
      if (is_alive(a)) inverse.reuse.face_anchors[0] = {face(a), first_corner(face(a))};
      if (is_alive(b)) inverse.reuse.face_anchors[1] = {face(b), first_corner(face(b))};
      unsubdivide_edge(step.vertex, step.reuse);
      return inverse;
    }
    case Step::Kind::set_face_point: {
      require(step.face, "set_face_point");
      inverse.kind = Step::Kind::set_face_point;
      inverse.face = step.face;
      const auto old = face_point(step.face);
      inverse.position = old ? *old : glm::dvec3(std::nan(""), 0.0, 0.0);
      set_face_point(step.face, std::isnan(step.position.x) ? std::nullopt : std::optional(step.position));
      return inverse;
    }
    case Step::Kind::set_position: {
      require(step.vertex, "set_position");
      inverse.kind = Step::Kind::set_position;
      inverse.vertex = step.vertex;
      inverse.position = position(step.vertex);
      set_position(step.vertex, step.position);
      return inverse;
    }
  }
  throw InvalidArgument("apply: unknown step kind");
}

// ---- compaction and equality
// -------------------------------------------------------------------------------

Mesh::CompactMap Mesh::compact() {
  CompactMap map;
  map.vertices.assign(vertex_capacity(), VertexId());
  map.edges.assign(edge_capacity(), EdgeId());
  map.faces.assign(face_capacity(), FaceId());
  map.corners.assign(corner_capacity(), CornerId());
  std::uint32_t n = 0;
  for (VertexId v : vertices()) map.vertices[v.index()] = VertexId(n++);
  n = 0;
  for (EdgeId e : edges()) map.edges[e.index()] = EdgeId(n++);
  n = 0;
  for (FaceId f : faces()) map.faces[f.index()] = FaceId(n++);
  n = 0;
  for (CornerId c : corners()) map.corners[c.index()] = CornerId(n++);

  auto mapped = [](const auto& table, auto h) { return h.valid() ? table[h.index()] : decltype(h)(); };

  // In place: a live element's new index is never above its old one, so moving them down in increasing order
  // never overwrites one still to be moved.
  for (std::uint32_t i = 0; i < map.vertices.size(); ++i) {
    const VertexId to = map.vertices[i];
    if (!to.valid()) continue;
    positions_[to.index()] = positions_[i];
    vertex_corner_[to.index()] = map.corners[vertex_corner_[i].index()];
  }
  for (std::uint32_t i = 0; i < map.edges.size(); ++i) {
    const EdgeId to = map.edges[i];
    if (!to.valid()) continue;
    const auto old = edges_[i].corner;
    edges_[to.index()].corner = {map.corners[old[0].index()], map.corners[old[1].index()]};
  }
  for (std::uint32_t i = 0; i < map.faces.size(); ++i) {
    const FaceId to = map.faces[i];
    if (!to.valid()) continue;
    FaceRecord r = faces_[i];
    r.corner = map.corners[r.corner.index()];
    faces_[to.index()] = r;
    if (!face_points_.empty()) face_points_[to.index()] = face_points_[i];
  }
  for (std::uint32_t i = 0; i < map.corners.size(); ++i) {
    const CornerId to = map.corners[i];
    if (!to.valid()) continue;
    const CornerRecord r = corners_[i];
    corners_[to.index()] = {map.vertices[r.vertex.index()], map.faces[r.face.index()],
                            map.corners[r.next.index()], map.corners[r.prev.index()],
                            mapped(map.edges, r.edge)};
  }
  positions_.resize(live_vertices_);
  vertex_corner_.resize(live_vertices_);
  edges_.resize(live_edges_);
  faces_.resize(live_faces_);
  if (!face_points_.empty()) face_points_.resize(live_faces_);
  corners_.resize(live_corners_);
  return map;
}

bool operator==(const Mesh& a, const Mesh& b) {
  if (a.num_vertices() != b.num_vertices() || a.num_edges() != b.num_edges() ||
      a.num_faces() != b.num_faces() || a.num_corners() != b.num_corners()) {
    return false;
  }
  // Live sets must match handle by handle; a removed element equals a missing one.
  auto same_alive = [&](auto tag, std::uint32_t ca, std::uint32_t cb) {
    using H = decltype(tag);
    std::uint32_t n = std::max(ca, cb);
    for (std::uint32_t i = 0; i < n; ++i) {
      if (a.is_alive(H(i)) != b.is_alive(H(i))) return false;
    }
    return true;
  };
  if (!same_alive(VertexId(), a.vertex_capacity(), b.vertex_capacity()) ||
      !same_alive(EdgeId(), a.edge_capacity(), b.edge_capacity()) ||
      !same_alive(FaceId(), a.face_capacity(), b.face_capacity()) ||
      !same_alive(CornerId(), a.corner_capacity(), b.corner_capacity())) {
    return false;
  }
  for (VertexId v : a.vertices()) {
    // Bit-for-bit: 0.0 and -0.0 differ, and a NaN would equal itself.
    if (std::memcmp(&a.positions_[v.index()], &b.positions_[v.index()], sizeof(glm::dvec3)) != 0)
      return false;
    if (a.vertex_corner_[v.index()] != b.vertex_corner_[v.index()]) return false;
  }
  for (EdgeId e : a.edges()) {
    if (a.edges_[e.index()].corner != b.edges_[e.index()].corner) return false;
  }
  for (FaceId f : a.faces()) {
    const auto& x = a.faces_[f.index()];
    const auto& y = b.faces_[f.index()];
    if (x.corner != y.corner || x.size != y.size || x.hole != y.hole) return false;
    const auto p = a.face_point(f), q = b.face_point(f);
    if (p.has_value() != q.has_value() || (p && std::memcmp(&*p, &*q, sizeof(glm::dvec3)) != 0)) return false;
  }
  for (CornerId c : a.corners()) {
    const auto& x = a.corners_[c.index()];
    const auto& y = b.corners_[c.index()];
    if (x.vertex != y.vertex || x.face != y.face || x.next != y.next || x.prev != y.prev ||
        x.edge != y.edge) {
      return false;
    }
  }
  return true;
}

}  // namespace dlfl

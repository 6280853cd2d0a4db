#include <dlfl/mesh.h>

#include <cmath>
#include <cstring>
#include <utility>

#include <dlfl/errors.h>

namespace dlfl {
namespace {
bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

template <class H>
std::string missing_message(const char* op, H h) {
  return std::string(op) + ": " + to_string(h) + " does not exist (removed or never created)";
}
}  // namespace

Mesh& Mesh::operator=(Mesh&& other) noexcept {
  if (this == &other) return *this;
  positions_ = std::move(other.positions_);
  vertex_corner_ = std::move(other.vertex_corner_);
  corners_ = std::move(other.corners_);
  edges_ = std::move(other.edges_);
  faces_ = std::move(other.faces_);
  live_vertices_ = std::exchange(other.live_vertices_, 0);
  live_edges_ = std::exchange(other.live_edges_, 0);
  live_faces_ = std::exchange(other.live_faces_, 0);
  live_hole_faces_ = std::exchange(other.live_hole_faces_, 0);
  live_corners_ = std::exchange(other.live_corners_, 0);
  attributes_ = std::move(other.attributes_);
  // Containers follow the data: the registry comes along and is told its new mesh.
  listeners_ = std::move(other.listeners_);
  if (listeners_.registry) listeners_.registry->mesh = this;
  return *this;
}

const std::shared_ptr<detail::MeshListeners>& Mesh::listeners() const {
  if (!listeners_.registry) {
    listeners_.registry = std::make_shared<detail::MeshListeners>();
    listeners_.registry->mesh = this;
  }
  return listeners_.registry;
}

std::uint32_t Mesh::capacity(ElementKind kind) const {
  switch (kind) {
    case ElementKind::vertex:
      return vertex_capacity();
    case ElementKind::edge:
      return edge_capacity();
    case ElementKind::face:
      return face_capacity();
    case ElementKind::corner:
      break;
  }
  return corner_capacity();
}

bool Mesh::is_alive(ElementKind kind, std::uint32_t index) const {
  switch (kind) {
    case ElementKind::vertex:
      return is_alive(VertexId(index));
    case ElementKind::edge:
      return is_alive(EdgeId(index));
    case ElementKind::face:
      return is_alive(FaceId(index));
    case ElementKind::corner:
      break;
  }
  return is_alive(CornerId(index));
}

void Mesh::reserve(std::size_t vertices, std::size_t edges, std::size_t faces, std::size_t corners) {
  positions_.reserve(vertices);
  vertex_corner_.reserve(vertices);
  edges_.reserve(edges);
  faces_.reserve(faces);
  corners_.reserve(corners);
  const std::size_t by_kind[] = {vertices, edges, faces, corners};
  for (const auto& entry : attributes_.entries()) {
    entry.column->reserve(by_kind[static_cast<int>(entry.column->kind())]);
  }
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

void Mesh::set_anchors(const detail::Reuse& reuse) {
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

void Mesh::set_hole(FaceId f, bool hole) {
  require(f, "set_hole");
  live_hole_faces_ += std::size_t(hole) - std::size_t(faces_[f.index()].hole);
  faces_[f.index()].hole = hole;
}

// ---- CREATEVERTEX and its inverse
// --------------------------------------------------------------------------

VertexId Mesh::create_vertex(const glm::dvec3& position, const detail::Reuse& reuse) {
  if (!finite(position)) throw InvalidArgument("create_vertex: position is not finite");
  if ((reuse.vertex.valid() && (reuse.vertex.index() >= vertex_capacity() || is_alive(reuse.vertex))) ||
      (reuse.face.valid() && (reuse.face.index() >= face_capacity() || is_alive(reuse.face))) ||
      (reuse.corners[0].valid() &&
       (reuse.corners[0].index() >= corner_capacity() || is_alive(reuse.corners[0])))) {
    throw InvalidArgument("create_vertex: a handle to reuse is not a removed element");
  }
  VertexId v = new_vertex(reuse.vertex);
  FaceId f = new_face(reuse.face, false);
  CornerId c = new_corner(reuse.corners[0]);
  positions_[v.index()] = position;
  vertex_corner_[v.index()] = c;
  corners_[c.index()] = {v, f, c, c, EdgeId()};
  faces_[f.index()].corner = c;
  faces_[f.index()].size = 1;
  apply_anchors(reuse);
  return v;
}

void Mesh::delete_vertex(VertexId v, const detail::Reuse& reuse) {
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
    case Step::Kind::create_vertex:
      return {.kind = Step::Kind::delete_vertex, .vertex = create_vertex(step.position, step.reuse)};
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
    case Step::Kind::subdivide_edge:
      return {.kind = Step::Kind::unsubdivide_edge,
              .vertex = subdivide_edge(step.edge, step.position, step.reuse)};
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
    // A setter is undone by the same setter with the old value.
    case Step::Kind::set_hole: {
      require(step.face, "set_hole");
      const bool old = is_hole(step.face);
      set_hole(step.face, step.hole);
      return {.kind = Step::Kind::set_hole, .hole = old, .face = step.face};
    }
    case Step::Kind::set_position: {
      require(step.vertex, "set_position");
      const glm::dvec3 old = position(step.vertex);
      set_position(step.vertex, step.position);
      return {.kind = Step::Kind::set_position, .vertex = step.vertex, .position = old};
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
  corners_.resize(live_corners_);
  attributes_.remap(map);
  if (listeners_.registry) listeners_.registry->compact(map);
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
  }
  for (CornerId c : a.corners()) {
    const auto& x = a.corners_[c.index()];
    const auto& y = b.corners_[c.index()];
    if (x.vertex != y.vertex || x.face != y.face || x.next != y.next || x.prev != y.prev ||
        x.edge != y.edge) {
      return false;
    }
  }
  return Mesh::same_attributes(a, b);
}

}  // namespace dlfl

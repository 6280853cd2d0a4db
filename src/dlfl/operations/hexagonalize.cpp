// hexagonalize: see hexagonalize.h. The result is assembled as a polygon soup (its vertices are new points,
// its faces new polygons) and built in one pass; the editor keeps the previous mesh whole, so undo is a swap.

#include <dlfl/operations/hexagonalize.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/format.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/detail/carry_attributes.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "hexagonalize";
// A corner's point: this far from its edge's midpoint towards its face's centroid.
constexpr double face_pull = 0.5;
// A point on a sharp edge whose two ends are cut: this fraction of the edge from its own end.
constexpr double end_share = 1.0 / 3.0;
// Two sharp edges at a vertex are in line when the sine of their angle is below this.
constexpr double in_line_tolerance = 1e-9;
constexpr std::uint32_t none = UINT32_MAX;

double degrees_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / std::numbers::pi;
}

// The side of edge(c) on which corner c lies (the side whose corner it is).
int side_of(const Mesh& m, CornerId c) { return m.corner(m.edge(c), 0) == c ? 0 : 1; }

class Builder {
 public:
  Builder(const Mesh& mesh, double angle) : m_(mesh) {
    find_sharp_edges(angle);
    add_corner_points();
    add_edge_points();
    add_hubs();
    for (VertexId v : m_.vertices()) {
      if (m_.is_point_sphere(v)) add_point(m_.position(v), origin_of(v));
    }
  }

  Mesh build(Origins& origins, std::vector<Origin>& corners) {
    for (FaceId f : m_.faces()) {
      if (m_.is_hole(f) || m_.size(f) < 2) continue;
      face_.clear();
      // The side from the point of c to that of next(c) cuts off next(c), as in the honeycomb.
      for (CornerId c : m_.corners(f)) push(point_[c.index()], origin_of(c), origin_of(m_.next(c)));
      add_face(origin_of(f));
    }
    for (VertexId v : m_.vertices()) {
      if (!m_.is_point_sphere(v)) add_vertex_faces(v);
    }
    Mesh out = build_mesh(soup_);
    set_origins(out, origins, corners);
    return out;
  }

 private:
  // A corner of the face being built: its point, the corner it stands for, and the origin of its side (the
  // edge to the next point).
  struct Entry {
    std::uint32_t point;
    Origin corner, side;
  };

  std::uint32_t add_point(const glm::dvec3& p, Origin origin) {
    soup_.positions.push_back(p);
    vertex_origin_.push_back(origin);
    return std::uint32_t(soup_.positions.size() - 1);
  }

  void push(std::uint32_t point, Origin corner, Origin side) { face_.push_back({point, corner, side}); }

  void add_face(Origin origin) {
    points_.clear();
    for (const Entry& entry : face_) {
      points_.push_back(entry.point);
      corner_origin_.push_back(entry.corner);
      side_origin_.push_back(entry.side);
    }
    soup_.add_face(points_);
    face_origin_.push_back(origin);
  }

  // Handles of `out` follow the soup (build_mesh.h): vertex i, face i, the j-th corner of face i at
  // offsets[i]
  // + j. The holes and point spheres build_mesh adds are found from their neighbours.
  void set_origins(const Mesh& out, Origins& origins, std::vector<Origin>& corners) const {
    origins.vertices.assign(out.vertex_capacity(), Origin{});
    origins.edges.assign(out.edge_capacity(), Origin{});
    origins.faces.assign(out.face_capacity(), Origin{});
    corners.assign(out.corner_capacity(), Origin{});
    std::copy(vertex_origin_.begin(), vertex_origin_.end(), origins.vertices.begin());
    std::copy(face_origin_.begin(), face_origin_.end(), origins.faces.begin());
    std::copy(corner_origin_.begin(), corner_origin_.end(), corners.begin());
    for (std::uint32_t k = 0; k < side_origin_.size(); ++k) {
      origins.edges[out.edge(CornerId(k)).index()] = side_origin_[k];
    }
    for (FaceId h : out.faces()) {
      if (!out.is_hole(h)) continue;
      // Across the hole's first corner lies a surface corner whose side halves an input border edge.
      const CornerId across = out.opposite(out.first_corner(h));
      const EdgeId e = side_origin_[across.index()].edge();
      origins.faces[h.index()] = origin_of(m_.is_hole(m_.face(e, 0)) ? m_.face(e, 0) : m_.face(e, 1));
    }
    for (VertexId v : out.vertices()) {
      if (!out.is_point_sphere(v)) continue;
      const VertexId source = origins.vertices[v.index()].vertex();
      const CornerId c = out.corner(v), input = m_.corner(source);
      origins.faces[out.face(c).index()] = origin_of(m_.face(input));
      corners[c.index()] = origin_of(input);
    }
  }

  bool on_border(EdgeId e) const { return m_.is_hole(m_.face(e, 0)) || m_.is_hole(m_.face(e, 1)); }

  void find_sharp_edges(double angle) {
    std::vector<glm::dvec3> normal(m_.face_capacity());
    for (FaceId f : m_.faces()) normal[f.index()] = face_normal(m_, f);
    sharp_.assign(m_.edge_capacity(), false);
    sharp_count_.assign(m_.vertex_capacity(), 0);
    for (EdgeId e : m_.edges()) {
      const glm::dvec3 a = normal[m_.face(e, 0).index()], b = normal[m_.face(e, 1).index()];
      const bool zero = a == glm::dvec3(0.0) || b == glm::dvec3(0.0);
      sharp_[e.index()] = on_border(e) || (!zero && degrees_between(a, b) > angle);
      if (!sharp_[e.index()]) continue;
      ++sharp_count_[m_.from(e).index()];
      ++sharp_count_[m_.to(e).index()];
    }
  }

  bool is_cut(VertexId v) const { return sharp_count_[v.index()] >= 2; }

  void add_corner_points() {
    point_.assign(m_.corner_capacity(), none);
    for (FaceId f : m_.faces()) {
      if (m_.is_hole(f) || m_.size(f) < 2) continue;
      const glm::dvec3 centroid = face_centroid(m_, f);
      for (CornerId c : m_.corners(f)) {
        const glm::dvec3 mid = 0.5 * (m_.position(m_.vertex(c)) + m_.position(m_.vertex(m_.next(c))));
        point_[c.index()] = add_point(mid + face_pull * (centroid - mid), origin_of(c));
      }
    }
  }

  // Per sharp edge and side: the point at the cut of that side's end (the same point on both sides when one
  // end is cut or the edge is on a border; none at an end that is not cut).
  void add_edge_points() {
    end_point_.assign(2 * std::size_t(m_.edge_capacity()), none);
    for (EdgeId e : m_.edges()) {
      if (!sharp_[e.index()]) continue;
      const VertexId ends[2] = {m_.from(e), m_.to(e)};
      const glm::dvec3 p0 = m_.position(ends[0]), p1 = m_.position(ends[1]);
      std::uint32_t* at = &end_point_[2 * std::size_t(e.index())];
      const bool cut0 = is_cut(ends[0]), cut1 = is_cut(ends[1]);
      if (cut0 && cut1 && !on_border(e)) {
        at[0] = add_point(p0 + end_share * (p1 - p0), origin_of(e));
        at[1] = add_point(p1 + end_share * (p0 - p1), origin_of(e));
      } else if (cut0 || cut1) {
        at[0] = at[1] = add_point(0.5 * (p0 + p1), origin_of(e));
      }
    }
  }

  // A cut vertex needs a hub unless it is inside the surface with exactly two sharp edges in line.
  bool needs_hub(VertexId v) const {
    if (sharp_count_[v.index()] != 2) return true;
    glm::dvec3 direction[2];
    int found = 0;
    for (CornerId c : m_.corners(v)) {
      if (m_.is_hole(m_.face(c))) return true;
      if (sharp_[m_.edge(c).index()]) {
        direction[found++] = glm::normalize(m_.position(m_.vertex(m_.next(c))) - m_.position(v));
      }
    }
    return glm::length(glm::cross(direction[0], direction[1])) > in_line_tolerance ||
           glm::dot(direction[0], direction[1]) > 0.0;
  }

  void add_hubs() {
    hub_.assign(m_.vertex_capacity(), none);
    for (VertexId v : m_.vertices()) {
      if (is_cut(v) && needs_hub(v)) hub_[v.index()] = add_point(m_.position(v), origin_of(v));
    }
  }

  // The face of v (the honeycomb's face around an old vertex), cut at its sharp edges if v is cut. Around
  // v, from corner c to the corner across edge(prev(c)): the points of c and prev(c), then the crossing of
  // edge(prev(c)), which carries the points of its far end and of v when it is sharp. Origins: the face <- v;
  // the corners at the points of c and prev(c) <- c (v's corner in their face); the side between them <- c
  // (as in the shrunken copy), the sides of the crossing of an edge and those along it <- that edge, the side
  // across v of an in-line cut <- v.
  void add_vertex_faces(VertexId v) {
    ring_.clear();
    for (CornerId c = m_.corner(v);;) {
      ring_.push_back(c);
      c = m_.prev_around_vertex(c);
      if (c == m_.corner(v)) break;
    }
    const std::size_t n = ring_.size();
    const auto crossing_is_cut = [&](std::size_t j) {
      return is_cut(v) && sharp_[m_.edge(m_.prev(ring_[j])).index()];
    };
    // Start after a cut crossing, so that every piece is complete when it is closed.
    std::size_t start = 0;
    while (start < n && !crossing_is_cut(start)) ++start;
    const bool cut = start < n;
    if (!cut) start = n - 1;
    face_.clear();
    bool dropped = false;
    // The sharp edge that the piece being built starts on.
    Origin piece_edge = origin_of(m_.edge(m_.prev(ring_[start])));
    if (cut) push(own_point(ring_[start]), Origin{}, piece_edge);
    for (std::size_t i = 1; i <= n; ++i) {
      const std::size_t j = (start + i) % n;
      const CornerId c = ring_[j], before = m_.prev(c);
      const EdgeId e = m_.edge(before);
      if (m_.is_hole(m_.face(c))) {
        dropped = true;
      } else {
        push(point_[c.index()], origin_of(c), origin_of(c));
        push(point_[before.index()], origin_of(c), origin_of(e));
      }
      if (!sharp_[e.index()]) continue;
      const std::uint32_t far = end_point_[2 * std::size_t(e.index()) + side_of(m_, before)];
      const std::uint32_t own = end_point_[2 * std::size_t(e.index()) + 1 - side_of(m_, before)];
      // Two points (far end first), one (the midpoint, far == own) or none.
      if (far != none) push(far, Origin{}, origin_of(e));
      if (own != far) push(own, Origin{}, origin_of(e));
      if (!crossing_is_cut(j)) continue;
      if (hub_[v.index()] != none) {
        push(hub_[v.index()], Origin{}, piece_edge);
      } else {
        face_.back().side = origin_of(v);
      }
      if (!dropped) add_face(origin_of(v));
      face_.clear();
      piece_edge = origin_of(e);
      push(own, Origin{}, piece_edge);
      dropped = false;
    }
    if (!cut) add_face(origin_of(v));
  }

  // The point of v's cut on the sharp edge crossed after corner c (edge(prev(c)) turned around v).
  std::uint32_t own_point(CornerId c) const {
    const CornerId before = m_.prev(c);
    return end_point_[2 * std::size_t(m_.edge(before).index()) + 1 - side_of(m_, before)];
  }

  const Mesh& m_;
  PolygonSoup soup_;
  // The origins of the soup's vertices, faces and corners, and of the side leaving each corner.
  std::vector<Origin> vertex_origin_, face_origin_, corner_origin_, side_origin_;
  std::vector<Entry> face_;
  std::vector<std::uint32_t> points_;
  std::vector<bool> sharp_;
  std::vector<std::uint32_t> sharp_count_, point_, end_point_, hub_;
  std::vector<CornerId> ring_;
};

}  // namespace

void check_hexagonalize(const Mesh& mesh, const HexagonalizeOptions& o) {
  if (!(o.angle >= 0.0 && o.angle <= 180.0)) {
    detail::refuse_worded(op_name, "angle", " = " + format_number(o.angle) + " is outside [0, 180]");
  }
  for (FaceId f : mesh.faces()) {
    if (!mesh.is_hole(f) && mesh.size(f) == 2) {
      detail::refuse(op_name, "mesh",
                     to_string(f) + " is a 2-gon, whose shrunken copy no polygon list holds");
    }
  }
  for (EdgeId e : mesh.edges()) {
    const FaceId f = mesh.face(e, 0), g = mesh.face(e, 1);
    if (f == g) detail::refuse(op_name, "mesh", to_string(e) + " has " + to_string(f) + " on both sides");
    if (mesh.is_hole(f) && mesh.is_hole(g))
      detail::refuse(op_name, "mesh", to_string(e) + " lies between two holes");
  }
}

Mesh hexagonalize(const Mesh& mesh, const HexagonalizeOptions& options, Origins* origins) {
  check_hexagonalize(mesh, options);
  Origins own;
  std::vector<Origin> corners;
  Mesh out = Builder(mesh, options.angle).build(origins ? *origins : own, corners);
  detail::carry_attributes(mesh, origins ? *origins : own, corners, out);
  return out;
}

std::vector<OperationSpec> detail::hexagonalize_operation_specs() {
  return {replace_operation(
      "hexagonalize",
      "the bricklayers' solution: hexagons on the faces, cut along sharp edges and borders, the shape kept "
      "(against the honeycomb's lateral artifacts)",
      {param(
           "angle", ParamType::number, 1.0,
           "an edge is sharp when its faces' normals differ by more than this (degrees); borders always are")
           .in(0, 180)},
      [](const Mesh& current, const Params& p) { return hexagonalize(current, {p.number("angle")}); },
      [](const Mesh& current, Params& p) { check_hexagonalize(current, {p.number("angle")}); })};
}

}  // namespace dlfl

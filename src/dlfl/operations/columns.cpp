// columns: a joint per vertex (CREATEFACEMANIFOLD of all its rings, then one INSERTEDGE per ring cutting it
// off as a face), a tube per edge (connect_faces), then the surface deleted (detail/shell_copy.h).
//
// A joint of valence k starts as the two faces of a polygon through its k rings in turn (the rings in the
// order of the edges around the vertex): the front face runs ring 0, ring 1, ..., and a chord from the
// first to the last corner of each ring splits that ring off the front as an n-gon (O(n)). What is left is
// the front's 2k-gon of chords and the back's kn-gon, so a joint has V kn, E kn + k, F k + 2 (a single ring,
// k = 1, needs no chord: V n, E n, F 2).

#include <dlfl/operations/columns.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include <dlfl/format.h>
#include <dlfl/operations/connect_faces.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/operations/detail/shell_copy.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "columns";
constexpr int max_sides = 256;
constexpr double largest_coordinate = 1e300;

void check(const Mesh& mesh, const ColumnsOptions& o) {
  if (!std::isfinite(o.thickness) || !(o.thickness > 0.0)) {
    detail::refuse_worded(op_name, "thickness",
                          " = " + format_number(o.thickness) + " must be finite and > 0");
  }
  if (o.sides < 3 || o.sides > max_sides) {
    detail::refuse_worded(op_name, "sides", " = " + std::to_string(o.sides) + " is outside [3, 256]");
  }
  double largest = 0.0;
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3& p = mesh.position(v);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  if (!(largest + 3.0 * o.thickness < largest_coordinate)) {
    detail::refuse(op_name, "thickness",
                   "the mesh's coordinates (up to " + format_number(largest) +
                       ") moved by the columns' size come too close to overflowing");
  }
}

// The cross-section of the column along edge e: its axis from the end with the smaller handle to the other,
// and two unit vectors across it, the same seen from both ends, so that the column is a straight prism.
struct Section {
  glm::dvec3 axis{0.0, 0.0, 1.0};
  glm::dvec3 across1{1.0, 0.0, 0.0};
  glm::dvec3 across2{0.0, 1.0, 0.0};
  double length = 0.0;
};

Section section_of(const Mesh& m, EdgeId e) {
  VertexId a = m.from(e), b = m.to(e);
  if (b < a) std::swap(a, b);
  Section s;
  const glm::dvec3 d = m.position(b) - m.position(a);
  s.length = glm::length(d);
  if (!(s.length > 0.0) || !std::isfinite(s.length)) return s;  // coincident ends: any frame
  s.axis = d / s.length;
  const glm::dvec3 ad = glm::abs(s.axis);
  const glm::dvec3 helper = ad.x <= ad.y && ad.x <= ad.z ? glm::dvec3(1, 0, 0)
                            : ad.y <= ad.z               ? glm::dvec3(0, 1, 0)
                                                         : glm::dvec3(0, 0, 1);
  s.across1 = glm::normalize(glm::cross(s.axis, helper));
  s.across2 = glm::cross(s.axis, s.across1);
  return s;
}

// The ring of edge e at vertex v: n points around the axis, counter-clockwise seen from beyond the ring
// along the edge (so the ring's face turns towards the edge's other end), starting at the point at angle 0
// of the section (j = 0 comes first either way).
void add_ring(const Mesh& m, EdgeId e, VertexId v, const ColumnsOptions& o, std::vector<glm::dvec3>& out) {
  const Section s = section_of(m, e);
  const VertexId lower = std::min(m.from(e), m.to(e));
  const bool along = v == lower;  // the ring faces along the axis
  const double distance = std::min(2.0 * o.thickness, s.length / 3.0);
  const glm::dvec3 centre = m.position(v) + (along ? distance : -distance) * s.axis;
  const int n = o.sides;
  for (int i = 0; i < n; ++i) {
    const int j = along ? i : (n - i) % n;  // against the axis the angles run backwards
    const double angle = 2.0 * std::numbers::pi * j / n;
    out.push_back(centre + o.thickness * (std::cos(angle) * s.across1 + std::sin(angle) * s.across2));
  }
}

// A joint to build: its rings' points, ring after ring, and the edge end each ring stands for (2e + side).
struct Joint {
  std::vector<glm::dvec3> points;
  std::vector<std::uint32_t> ends;
};

std::vector<Joint> planned_joints(const Mesh& m, const ColumnsOptions& o) {
  std::vector<Joint> out;
  out.reserve(m.num_vertices());
  for (VertexId v : m.vertices()) {
    if (m.is_point_sphere(v)) continue;
    Joint joint;
    for (CornerId c : m.corners(v)) {
      const EdgeId e = m.edge(c);
      add_ring(m, e, v, o, joint.points);
      joint.ends.push_back(2 * e.index() + (m.corner(e, 0) == c ? 0 : 1));
    }
    out.push_back(std::move(joint));
  }
  return out;
}

}  // namespace

void columns(Transaction& tx, const ColumnsOptions& options) {
  const Mesh& m = tx.mesh();
  check(m, options);
  const std::vector<Joint> joints = planned_joints(m, options);
  const std::uint32_t old_edges = m.edge_capacity();
  detail::remove_surface(tx);
  const std::size_t n = std::size_t(options.sides);
  // Per old edge end: the corner of its ring's face at the section's angle 0.
  std::vector<CornerId> starts(2 * std::size_t(old_edges));
  std::vector<CornerId> front;
  for (const Joint& joint : joints) {
    const std::size_t k = joint.ends.size();
    front.assign(joint.points.size(), CornerId());
    tx.create_face_manifold(joint.points, {}, front);
    for (std::size_t r = 0; r < k; ++r) {
      // The chord from the ring's first corner to its last splits the ring off as the part of its first.
      if (k > 1) tx.insert_edge(front[r * n], front[r * n + n - 1]);
      starts[joint.ends[r]] = front[r * n];
    }
  }
  for (std::uint32_t e = 0; e < old_edges; ++e) {
    if (!starts[2 * e].valid()) continue;  // not an edge of the surface
    ConnectFacesOptions o;
    o.corner1 = starts[2 * e];
    o.corner2 = starts[2 * e + 1];
    connect_faces(tx, m.face(o.corner1), m.face(o.corner2), o);
  }
}

void check_columns(const Mesh& mesh, const ColumnsOptions& options) { check(mesh, options); }

std::vector<OperationSpec> detail::columns_operation_specs() {
  return {edit_operation(
      "columns", "the frame of wireframe from n-sided columns along the edges and joints at the vertices",
      {param("thickness", ParamType::number, 0.05, "the circumradius of each column's cross-section")
           .range(0.0, std::numeric_limits<double>::infinity(), true, false),
       param("sides", ParamType::integer, 4, "the sides of each column").in(3, max_sides)},
      "V'=2En, E'=3En+2E-V1, F'=2V+En-V1 (V1: vertices of valence 1; Euler characteristic 2V-2E)",
      [](Transaction& tx, const Params& p) {
        columns(tx, {p.number("thickness"), int(p.integer("sides"))});
        return Params{};
      },
      [](const Mesh& mesh, Params& p) {
        check(mesh, {p.number("thickness"), int(p.integer("sides"))});
      })};
}
}  // namespace dlfl

// wireframe: an inset ring on every face (detail/extrusion_rings.h), then the shell (detail/shell_copy.h)
// with every inset face punched.

#include <dlfl/operations/wireframe.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include <dlfl/format.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/detail/extrusion_rings.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/operations/detail/shell_copy.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "wireframe";
// Coordinates up to this, moved by at most thickness + width, stay far from overflowing.
constexpr double largest_coordinate = 1e300;

void require_positive(std::string_view param, double x) {
  if (!std::isfinite(x) || !(x > 0.0)) {
    detail::refuse_worded(op_name, param, " = " + format_number(x) + " must be finite and > 0");
  }
}

void check(const Mesh& mesh, const WireframeOptions& o) {
  require_positive("thickness", o.thickness);
  require_positive("width", o.width);
  double largest = 0.0;
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3& p = mesh.position(v);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  if (!(largest + o.thickness + o.width < largest_coordinate)) {
    detail::refuse(op_name, largest + o.thickness < largest_coordinate ? "width" : "thickness",
                   "the mesh's coordinates (up to " + format_number(largest) +
                       ") moved by thickness + width come too close to overflowing");
  }
}

// The inset corners of f: each where the two edges at it, moved inward by `width` in the face's plane,
// meet (the miter point); a corner whose miter point is undefined (no normal, a reversal) or more than half
// way to the centroid moves half way to the centroid instead, so that thin faces keep an opening.
std::vector<glm::dvec3> inset_corners(const Mesh& m, const std::vector<CornerId>& corners, FaceId f,
                                      double width) {
  const glm::dvec3 n = face_normal(m, f), c = face_centroid(m, f);
  const std::size_t k = corners.size();
  std::vector<glm::dvec3> out(k);
  auto inward = [&](const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 side = glm::cross(n, b - a);
    const double length = glm::length(side);
    return length > 0.0 ? side / length : glm::dvec3(0.0);
  };
  for (std::size_t i = 0; i < k; ++i) {
    const glm::dvec3& prev = m.position(m.vertex(corners[(i + k - 1) % k]));
    const glm::dvec3& p = m.position(m.vertex(corners[i]));
    const glm::dvec3& next = m.position(m.vertex(corners[(i + 1) % k]));
    const glm::dvec3 a = inward(prev, p), b = inward(p, next);
    const double denominator = 1.0 + glm::dot(a, b);
    const glm::dvec3 half = 0.5 * (c - p);
    const bool defined = a != glm::dvec3(0.0) && b != glm::dvec3(0.0) && denominator > 1e-9;
    const glm::dvec3 miter = defined ? width / denominator * (a + b) : half;
    out[i] = p + (glm::length(miter) <= glm::length(half) ? miter : half);
  }
  return out;
}

// Room for everything wireframe adds, so that the mesh's arrays and the record are filled once rather than
// grown (each growth copies them and faults in fresh memory). With S the sides of the surface faces and H
// those of the hole faces: the rings add S vertices, 2S edges, 2S faces (S point spheres merged away, S
// splits) and 4S corners in 3S steps; the copy of the V1 = V + S vertices and E1 = E + 2S edges adds at
// most V1 vertices, E1 edges, V1 + E1 faces and V1 + 2 E1 corners in V1 + E1 steps and a set_hole per hole
// face; each tube of n sides adds n edges, at most n faces and 2n corners in n steps.
void reserve_room(Transaction& tx) {
  const Mesh& m = tx.mesh();
  std::size_t sides = 0, hole_sides = 0, holes = 0;
  for (FaceId f : m.faces()) {
    if (m.size(f) < 2) continue;
    if (m.is_hole(f)) {
      hole_sides += m.size(f);
      ++holes;
    } else {
      sides += m.size(f);
    }
  }
  const std::size_t v1 = m.num_vertices() + sides, e1 = m.num_edges() + 2 * sides;
  const std::size_t tube_sides = sides + hole_sides;
  tx.reserve(3 * sides + v1 + e1 + holes + tube_sides, m.vertex_capacity() + sides + v1,
             m.edge_capacity() + 2 * sides + e1 + tube_sides,
             m.face_capacity() + 2 * sides + v1 + e1 + tube_sides,
             m.corner_capacity() + 4 * sides + v1 + 2 * e1 + 2 * tube_sides);
}

}  // namespace

std::vector<VertexId> wireframe(Transaction& tx, const WireframeOptions& options) {
  const Mesh& m = tx.mesh();
  check(m, options);
  reserve_room(tx);
  std::vector<FaceId> surface;
  for (FaceId f : m.faces()) {
    if (!m.is_hole(f) && m.size(f) >= 2) surface.push_back(f);
  }
  std::vector<FaceId> openings;
  openings.reserve(surface.size());
  for (FaceId f : surface) {
    const std::vector<CornerId> corners = detail::corners_from(m, m.first_corner(f));
    const std::vector<glm::dvec3> inset = inset_corners(m, corners, f, options.width);
    openings.push_back(m.face(detail::grow_quad_ring(tx, corners, inset).front()));
  }
  const std::vector<glm::dvec3> inner = detail::inner_positions(m, op_name, "thickness", options.thickness);
  const detail::MirroredCopy copy = detail::add_shell(tx, inner, openings, false);
  std::vector<VertexId> out;
  for (VertexId v : copy.vertices) {
    if (v.valid()) out.push_back(v);
  }
  return out;
}

void check_wireframe(const Mesh& mesh, const WireframeOptions& options) { check(mesh, options); }

std::vector<OperationSpec> detail::wireframe_operation_specs() {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  return {edit_operation(
      "wireframe", "every edge a beam and every face an opening through the frame (genus E - V + 1)",
      {param("thickness", ParamType::number, 0.05, "the depth of the frame, along the vertex normals")
           .range(0.0, infinity, true, false),
       param("width", ParamType::number, 0.05, "how far each opening lies inside the edges of its face")
           .range(0.0, infinity, true, false)},
      "closed: V'=2V+4E, E'=12E, F'=6E (Euler characteristic 2V-2E)",
      [](Transaction& tx, const Params& p) {
        return Params{{"vertices", wireframe(tx, {p.number("thickness"), p.number("width")})}};
      },
      [](const Mesh& mesh, Params& p) {
        check(mesh, {p.number("thickness"), p.number("width")});
      })};
}
}  // namespace dlfl

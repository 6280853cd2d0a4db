#include <dlfl/analysis/convex_polyhedron.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include <dlfl/errors.h>
#include <dlfl/format.h>

namespace dlfl {
namespace {

std::string format_point(const glm::dvec3& p) {
  // Appended rather than "(" + ...: GCC 12 warns (-Wrestrict) about a string inserted at the front.
  std::string s = "(";
  s.append(format_number(p.x)).append(", ").append(format_number(p.y)).append(", ");
  return s.append(format_number(p.z)).append(")");
}

// Solid angle of the triangle (a, b, c) seen from the origin (Van Oosterom and Strackee); positive when the
// triangle is counter-clockwise seen from the origin's outside, i.e. oriented away from it.
double solid_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double numerator = glm::dot(a, glm::cross(b, c));
  const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

ConvexityViolation topological(std::string message) { return {true, std::move(message)}; }
ConvexityViolation geometric(std::string message) { return {false, std::move(message)}; }

}  // namespace

double FacePlane::distance(const glm::dvec3& p) const { return glm::dot(normal, p) - offset; }

FacePlane face_plane(const Mesh& mesh, FaceId f) {
  glm::dvec3 newell(0.0), sum(0.0);
  for (CornerId c : mesh.corners(f)) {
    const glm::dvec3& p = mesh.position(mesh.vertex(c));
    const glm::dvec3& q = mesh.position(mesh.vertex(mesh.next(c)));
    newell += glm::cross(p, q);
    sum += p;
  }
  const double area2 = glm::length(newell);
  FacePlane plane;
  if (area2 == 0.0) return plane;
  plane.normal = newell / area2;
  plane.offset = glm::dot(plane.normal, sum / double(mesh.size(f)));
  return plane;
}

double bounding_box_diagonal(const Mesh& mesh) {
  glm::dvec3 lo(0.0), hi(0.0);
  bool first = true;
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3& p = mesh.position(v);
    lo = first ? p : glm::min(lo, p);
    hi = first ? p : glm::max(hi, p);
    first = false;
  }
  return glm::length(hi - lo);
}

glm::dvec3 vertex_centroid(const Mesh& mesh) {
  glm::dvec3 sum(0.0);
  for (VertexId v : mesh.vertices()) sum += mesh.position(v);
  return mesh.num_vertices() == 0 ? sum : sum / double(mesh.num_vertices());
}

std::optional<ConvexityViolation> convexity_violation(const Mesh& mesh, const glm::dvec3& centre,
                                                      const ConvexityOptions& options) {
  constexpr double pi = std::numbers::pi;
  if (mesh.num_faces() == 0) return topological("the mesh has no faces");
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f)) return topological(to_string(f) + " is a hole: the mesh is open, not a polyhedron");
    if (mesh.size(f) < 3) {
      if (mesh.size(f) == 1) {
        return topological(to_string(mesh.vertex(mesh.first_corner(f))) + " is a point sphere (no edge)");
      }
      return topological(to_string(f) + " has 2 sides");
    }
  }
  const double tolerance = options.relative_tolerance * bounding_box_diagonal(mesh);

  // Planes, planarity, and strictly convex polygons.
  std::vector<FacePlane> planes(mesh.face_capacity());
  for (FaceId f : mesh.faces()) {
    const FacePlane plane = face_plane(mesh, f);
    planes[f.index()] = plane;
    if (plane.normal == glm::dvec3(0.0)) return geometric(to_string(f) + " is degenerate (zero area)");
    double turning = 0.0;
    for (CornerId c : mesh.corners(f)) {
      const VertexId v = mesh.vertex(c);
      const glm::dvec3& p = mesh.position(v);
      const double off = plane.distance(p);
      if (std::abs(off) > tolerance) {
        return geometric(to_string(f) + " is not planar: " + to_string(v) + " is " + format_number(off) +
                         " off its plane (tolerance " + format_number(tolerance) + ")");
      }
      const glm::dvec3 in = p - mesh.position(mesh.vertex(mesh.prev(c)));
      const glm::dvec3 out = mesh.position(mesh.vertex(mesh.next(c))) - p;
      const double turn = std::atan2(glm::dot(glm::cross(in, out), plane.normal), glm::dot(in, out));
      if (!(turn > options.angle_tolerance)) {
        return geometric(to_string(f) +
                         " is not a strictly convex polygon: its boundary does not turn left at " +
                         to_string(v));
      }
      turning += turn;
    }
    if (std::abs(turning - 2.0 * pi) > 1e-6) {
      return geometric(to_string(f) + " is not a convex polygon: its boundary turns around " +
                       format_number(turning / (2.0 * pi)) + " times");
    }
  }

  // Edges: convex, faces not coplanar. The signed exterior angle is positive when the edge bends the surface
  // away from the outside; (n0 x n1) then points along the edge as its side-0 face runs it.
  for (EdgeId e : mesh.edges()) {
    const FaceId f0 = mesh.face(e, 0), f1 = mesh.face(e, 1);
    const glm::dvec3 n0 = planes[f0.index()].normal, n1 = planes[f1.index()].normal;
    const glm::dvec3 along = glm::normalize(mesh.position(mesh.to(e)) - mesh.position(mesh.from(e)));
    const double angle = std::atan2(glm::dot(glm::cross(n0, n1), along), glm::dot(n0, n1));
    if (std::abs(angle) <= options.angle_tolerance) {
      return geometric("faces " + to_string(f0) + " and " + to_string(f1) + " across " + to_string(e) +
                       " are coplanar");
    }
    if (angle < 0.0) {
      return geometric(to_string(e) + " is concave: faces " + to_string(f0) + " and " + to_string(f1) +
                       " meet at an exterior angle of " + format_number(angle * 180.0 / pi) + " degrees");
    }
  }

  // The centre: strictly inside every face plane, and the surface wraps around it exactly once.
  double total = 0.0;
  for (FaceId f : mesh.faces()) {
    const double d = planes[f.index()].distance(centre);
    if (!(d < -tolerance)) {
      return geometric("the centre " + format_point(centre) + " is not strictly inside the plane of " +
                       to_string(f) + " (distance " + format_number(d) + ")");
    }
    const CornerId first = mesh.first_corner(f);
    const glm::dvec3 a = mesh.position(mesh.vertex(first)) - centre;
    for (CornerId c = mesh.next(first); mesh.next(c) != first; c = mesh.next(c)) {
      total += solid_angle(a, mesh.position(mesh.vertex(c)) - centre,
                           mesh.position(mesh.vertex(mesh.next(c))) - centre);
    }
  }
  const double sheets = total / (4.0 * pi);
  if (std::abs(sheets - 1.0) > 0.25) {
    return geometric("the faces wrap " + format_number(sheets) + " times around the centre " +
                     format_point(centre) + ": not the boundary of one convex body");
  }
  return std::nullopt;
}

bool is_convex_polyhedron(const Mesh& mesh, const glm::dvec3& centre, const ConvexityOptions& options) {
  return !convexity_violation(mesh, centre, options).has_value();
}

void require_convex_polyhedron(const Mesh& mesh, const glm::dvec3& centre, const std::string& context,
                               const ConvexityOptions& options) {
  const auto violation = convexity_violation(mesh, centre, options);
  if (!violation) return;
  const std::string message =
      context + ": input is not a strictly convex polyhedron around its centre: " + violation->message;
  if (violation->topological) throw TopologyError(message);
  throw InvalidArgument(message);
}

}  // namespace dlfl

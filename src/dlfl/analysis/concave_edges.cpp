#include <dlfl/analysis/concave_edges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/geometry.h>

namespace dlfl {
namespace {

// The angle between two unit vectors, accurate near 0 (where the bends of a fine mesh are).
double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

ConcaveEdges concave_edges(const Mesh& mesh, double relative_tolerance, std::vector<bool>* concave) {
  if (!(relative_tolerance >= 0.0 && std::isfinite(relative_tolerance))) {
    throw InvalidArgument("concave_edges: relative_tolerance = " + format_number(relative_tolerance) +
                          " must be finite and >= 0");
  }
  const double tolerance = relative_tolerance * bounding_box_diagonal(mesh);
  // Each face's plane and centroid, once.
  std::vector<FacePlane> planes(mesh.face_capacity());
  std::vector<glm::dvec3> centroids(mesh.face_capacity());
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f)) continue;
    planes[f.index()] = face_plane(mesh, f);
    centroids[f.index()] = face_centroid(mesh, f);
  }
  constexpr double degrees = 180.0 / std::numbers::pi;
  if (concave) concave->assign(mesh.edge_capacity(), false);
  ConcaveEdges out;
  double bend_sum = 0.0;
  for (EdgeId e : mesh.edges()) {
    const FaceId f = mesh.face(mesh.corner(e, 0)), g = mesh.face(mesh.corner(e, 1));
    if (f == g || mesh.is_hole(f) || mesh.is_hole(g)) continue;
    const FacePlane& pf = planes[f.index()];
    const FacePlane& pg = planes[g.index()];
    if (pf.normal == glm::dvec3(0.0) || pg.normal == glm::dvec3(0.0)) continue;  // no plane to be above
    ++out.measured;
    const double bend = angle_between(pf.normal, pg.normal) * degrees;
    bend_sum += bend;
    if (pf.distance(centroids[g.index()]) > tolerance || pg.distance(centroids[f.index()]) > tolerance) {
      ++out.concave;
      if (concave) (*concave)[e.index()] = true;
      out.worst_concave_degrees = std::max(out.worst_concave_degrees, bend);
    }
  }
  if (out.measured > 0) out.mean_dihedral_degrees = bend_sum / double(out.measured);
  return out;
}

}  // namespace dlfl

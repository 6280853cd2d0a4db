#include <dlfl/analysis/detail/best_fit_plane.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include <dlfl/geometry.h>
#include <dlfl/navigation.h>

namespace dlfl::detail {
namespace {

// The unit eigenvector of the smallest eigenvalue of the symmetric matrix a, by cyclic Jacobi rotations
// (each zeroes one off-diagonal entry; a few sweeps reach rounding level for a 3 x 3 matrix).
glm::dvec3 smallest_eigenvector(double a[3][3]) {
  double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  constexpr int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int sweep = 0; sweep < 50; ++sweep) {
    if (a[0][1] == 0.0 && a[0][2] == 0.0 && a[1][2] == 0.0) break;
    for (const auto& [p, q] : pairs) {
      if (a[p][q] == 0.0) continue;
      const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
      const double t = std::abs(theta) > 1e150
                           ? 0.5 / theta
                           : std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
      for (int k = 0; k < 3; ++k) {
        const double kp = a[k][p], kq = a[k][q];
        a[k][p] = c * kp - s * kq;
        a[k][q] = s * kp + c * kq;
      }
      for (int k = 0; k < 3; ++k) {
        const double pk = a[p][k], qk = a[q][k];
        a[p][k] = c * pk - s * qk;
        a[q][k] = s * pk + c * qk;
      }
      a[p][q] = a[q][p] = 0.0;  // zero by construction; rounding would leave a trace
      for (int k = 0; k < 3; ++k) {
        const double kp = v[k][p], kq = v[k][q];
        v[k][p] = c * kp - s * kq;
        v[k][q] = s * kp + c * kq;
      }
    }
  }
  int smallest = 0;
  for (int i = 1; i < 3; ++i) {
    if (a[i][i] < a[smallest][smallest]) smallest = i;
  }
  const glm::dvec3 n(v[0][smallest], v[1][smallest], v[2][smallest]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0, 0, 1);
}

}  // namespace

Plane best_fit_plane(const Mesh& m, FaceId f) {
  Plane plane;
  plane.point = face_centroid(m, f);
  double a[3][3] = {};
  for (VertexId v : vertices(m, f)) {
    const glm::dvec3 d = m.position(v) - plane.point;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) a[i][j] += d[i] * d[j];
    }
  }
  plane.normal = smallest_eigenvector(a);
  return plane;
}

double face_nonplanarity(const Mesh& m, FaceId f, const Plane& plane) {
  double largest = 0.0, perimeter = 0.0;
  for (CornerId c : m.corners(f)) {
    const glm::dvec3& p = m.position(m.vertex(c));
    largest = std::max(largest, std::abs(glm::dot(plane.normal, p - plane.point)));
    perimeter += glm::length(m.position(m.vertex(m.next(c))) - p);
  }
  return perimeter > 0.0 ? largest / (perimeter / m.size(f)) : 0.0;
}

}  // namespace dlfl::detail

// Ear clipping: see ear_clipping.h.

#include <dlfl/detail/ear_clipping.h>

#include <glm/geometric.hpp>
#include <limits>
#include <utility>

#include <dlfl/geometry.h>

namespace dlfl::detail {
namespace {

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// In the closed triangle a, b, c (counter-clockwise) but not one of its corners: a corner there would make
// the cut cross or touch the polygon's boundary.
bool inside_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  if (p == a || p == b || p == c) return false;
  return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
}

}  // namespace

void EarClipper::start(const Mesh& m, FaceId f) {
  // (u, w, normal) is right-handed, so the face, counter-clockwise about its normal, is counter-clockwise in
  // (u, w) too.
  glm::dvec3 normal = face_normal(m, f);
  if (normal == glm::dvec3(0.0)) normal = glm::dvec3(0, 0, 1);  // degenerate: any plane will do
  const glm::dvec3 a = glm::abs(normal);
  const glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                          : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                                   : glm::dvec3(0, 0, 1);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, normal));
  const glm::dvec3 w = glm::cross(normal, u);
  const glm::dvec3 origin = m.position(m.vertex(m.first_corner(f)));
  vertex_.clear();
  point_.clear();
  prev_.clear();
  next_.clear();
  for (CornerId c : m.corners(f)) {
    const glm::dvec3 d = m.position(m.vertex(c)) - origin;
    vertex_.push_back(m.vertex(c));
    point_.emplace_back(glm::dot(d, u), glm::dot(d, w));
  }
  const auto n = static_cast<std::uint32_t>(vertex_.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    prev_.push_back((i + n - 1) % n);
    next_.push_back((i + 1) % n);
  }
  remaining_ = n;
  at_ = 0;
  ear_.assign(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) ear_[i] = is_ear(i);
}

// Twice the signed area of the triangle prev(i), i, next(i): positive where the polygon turns left.
double EarClipper::turn(std::uint32_t i) const {
  const glm::dvec2& p = point_[prev_[i]];
  return cross(point_[i] - p, point_[next_[i]] - p);
}

// How many of i's two neighbours could still be cut off once i is (both, when a triangle is left).
int EarClipper::neighbours_left_cuttable(std::uint32_t i) const {
  if (remaining_ <= 4) return 2;
  const std::uint32_t a = prev_[i], b = next_[i];
  return int(vertex_[prev_[a]] != vertex_[b]) + int(vertex_[a] != vertex_[next_[b]]);
}

bool EarClipper::is_ear(std::uint32_t i) const {
  if (!cuttable(i) || turn(i) <= 0.0) return false;
  const std::uint32_t a = prev_[i], b = next_[i];
  for (std::uint32_t j = next_[b]; j != a; j = next_[j]) {
    if (inside_triangle(point_[j], point_[a], point_[i], point_[b])) return false;
  }
  return true;
}

// The node to cut off next, or `none`: an ear if there is one, else the most convex cuttable corner; among
// those, one that leaves its neighbours cuttable where it can.
std::uint32_t EarClipper::next_tip() {
  for (int pass = 0; pass < 2; ++pass) {
    std::uint32_t best = none;
    int best_left = -1;
    std::uint32_t j = at_;
    for (std::uint32_t k = 0; k < remaining_; ++k, j = next_[j]) {
      if (!ear_[j]) continue;
      const int left = neighbours_left_cuttable(j);
      if (left == 2) return j;
      if (left > best_left) {
        best = j;
        best_left = left;
      }
    }
    if (best != none) return best;
    if (pass == 1) break;
    // Cutting an ear can free a corner away from it (its neighbours' flags are the only ones kept up to
    // date), so look again with every flag fresh before giving up on ears.
    for (std::uint32_t k = 0; k < remaining_; ++k, j = next_[j]) ear_[j] = is_ear(j);
  }
  std::uint32_t best = none;
  std::pair<int, double> best_rank(-1, -std::numeric_limits<double>::infinity());
  std::uint32_t j = at_;
  for (std::uint32_t k = 0; k < remaining_; ++k, j = next_[j]) {
    const std::pair<int, double> rank(neighbours_left_cuttable(j), turn(j));
    if (cuttable(j) && rank > best_rank) {
      best = j;
      best_rank = rank;
    }
  }
  return best;
}

std::optional<EarClipper::Ear> EarClipper::cut() {
  if (remaining_ <= 3) return std::nullopt;
  const std::uint32_t tip = next_tip();
  if (tip == none) return std::nullopt;
  const std::uint32_t a = prev_[tip], b = next_[tip];
  next_[a] = b;
  prev_[b] = a;
  --remaining_;
  ear_[a] = is_ear(a);
  ear_[b] = is_ear(b);
  at_ = b;
  return Ear{a, tip, b};
}

}  // namespace dlfl::detail

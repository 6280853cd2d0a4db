// The hull in four stages.
//
// 1. The exact hull as triangles: a randomized incremental construction (Clarkson and Shor). A point
//    strictly above a face of the current hull removes the faces it sees, and a cone of triangles joins it
//    to the horizon. Every decision is an exact orientation sign (exact_orientation.h), so the triangles
//    are consistent whatever the input; a point on a face's plane is not above it, so points on the hull's
//    faces and edges are never added unless they were corners when they came. The points are inserted in
//    a biased randomized order (Amenta, Choi and Rote, "Incremental constructions con BRIO": random rounds
//    of doubling size, each along a space-filling curve, on which the points are also numbered), and each
//    is located by a stochastic visibility walk (Devillers, Pion and Teillaud, "Walking in a
//    triangulation") over the triangles as seen from a point inside the first tetrahedron, from where the
//    previous point was placed: consecutive points are close, so the walks are short, and neighbouring
//    insertions touch neighbouring memory.
// 2. Faces: triangles across an edge whose fourth point lies exactly on their plane are merged, and so are
//    triangles whose normals differ by at most `hull_angle_tolerance`, as long as the merged face stays
//    within `hull_planarity_tolerance` of its plane. Each merged face is a disk whose boundary is its
//    polygon; the vertices inside it are dropped.
// 3. Corners: where a face turns by at most the angle tolerance (a vertex on, or nearly on, the segment
//    between its neighbours), the vertex goes. When it lies on two faces only (on the edge between them) it
//    is taken out of both; otherwise the hull of the remaining vertices is built again without it.
// 4. What the convexity check looks at and the stages above have not settled is checked (the depth of the
//    centroid, the angles at merged faces, with half the working angle), and the mesh is assembled directly
//    from the corners.
//
// The points are first scaled by a power of two (which changes no sign) so that the largest coordinate is
// in [1, 2), as the exact predicates want.

#include <dlfl/operations/detail/convex_hull_3d.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <random>
#include <utility>

#include <dlfl/detail/large_allocator.h>
#include <dlfl/format.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/operations/detail/exact_orientation.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl::detail {
namespace {

// Every array here grows with the points: huge pages, and blocks that come back mapped (large_allocator.h).
template <class T>
using Array = LargeVector<T>;

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
// Rounds of stage 3 that rebuild the hull; each drops at least one vertex, and one is almost always enough.
constexpr int max_rounds = 64;
// Stage 4 asks for half the working angle (the convexity check asks for a quarter).
constexpr double verified_angle = hull_angle_tolerance / 2;

using NameOf = std::function<std::string(std::uint32_t)>;

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The points times 2^-e, with the largest coordinate magnitude in [1, 2); coordinates below 2^-200 of that
// are taken as 0 (far below every tolerance), so that the predicates stay exact.
Array<glm::dvec3> scaled_points(std::span<const glm::dvec3> points) {
  double largest = 0.0;
  for (const glm::dvec3& p : points)
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const int e = largest > 0.0 ? std::ilogb(largest) : 0;
  const double tiny = std::ldexp(1.0, -200), factor = std::ldexp(1.0, -e);  // a power of two: exact
  Array<glm::dvec3> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double x = points[i][k] * factor;
      out[i][k] = std::abs(x) < tiny ? 0.0 : x;
    }
  }
  return out;
}

double box_diagonal(std::span<const glm::dvec3> points) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

// 10 bits of each coordinate, relative to the bounding box, interleaved: the cell of the point along a
// Z-order curve.
std::uint32_t cell_code(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& scale) {
  auto spread = [](double x) {
    // Written so that a NaN falls into cell 0 too: converting it to an integer is undefined.
    std::uint32_t v = x > 0.0 ? static_cast<std::uint32_t>(std::min(x, 1023.0)) : 0u;
    v = (v | v << 16) & 0x030000FFu;
    v = (v | v << 8) & 0x0300F00Fu;
    v = (v | v << 4) & 0x030C30C3u;
    return (v | v << 2) & 0x09249249u;
  };
  const glm::dvec3 x = (p - lo) * scale;
  return spread(x.x) | spread(x.y) << 1 | spread(x.z) << 2;
}

// The point indices in the order of their cells along the curve (two stable counting passes of 15 bits).
Array<std::uint32_t> curve_order(const Array<glm::dvec3>& q) {
  glm::dvec3 lo = q[0], hi = q[0];
  for (const glm::dvec3& p : q) lo = glm::min(lo, p), hi = glm::max(hi, p);
  // An axis without extent (every point on one plane) puts every point into its cell 0; so does one so thin
  // that 1023 over its extent is not finite, where a scale of infinity would make 0 * inf = NaN.
  glm::dvec3 scale(0.0);
  for (int k = 0; k < 3; ++k) {
    const double s = 1023.0 / (hi[k] - lo[k]);
    scale[k] = std::isfinite(s) ? s : 0.0;
  }
  Array<std::uint32_t> code(q.size()), order(q.size()), sorted(q.size());
  for (std::uint32_t i = 0; i < q.size(); ++i) code[i] = cell_code(q[i], lo, scale), order[i] = i;
  Array<std::uint32_t> count(std::size_t(1) << 15);
  for (int shift : {0, 15}) {
    std::fill(count.begin(), count.end(), 0u);
    for (std::uint32_t i : order) ++count[(code[i] >> shift) & 0x7FFFu];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) sum += std::exchange(c, sum);
    for (std::uint32_t i : order) sorted[count[(code[i] >> shift) & 0x7FFFu]++] = i;
    std::swap(order, sorted);
  }
  return order;
}

// True if a boundary running along `in` then `out` turns left by more than the angle whose tangent is
// `tan_angle` (small), seen along `normal`: atan2(y, x) > angle, as the convexity check measures it.
bool turns_left(const glm::dvec3& in, const glm::dvec3& out, const glm::dvec3& normal, double tan_angle) {
  const double y = glm::dot(glm::cross(in, out), normal), x = glm::dot(in, out);
  if (y > 0.0) return x <= 0.0 || y > tan_angle * x;
  return y == 0.0 && x < 0.0;
}

// True if the directions a and b (any lengths) differ by at most the angle whose tangent is `tan_angle`.
bool within_angle(const glm::dvec3& a, const glm::dvec3& b, double tan_angle) {
  const double d = glm::dot(a, b);
  return d > 0.0 && glm::length(glm::cross(a, b)) <= tan_angle * d;
}

// ---- stage 1 ---------------------------------------------------------------------------------------------

struct Triangle {
  std::array<std::uint32_t, 3> v{none, none, none};  // v[0] == none: a free slot
  std::uint32_t mark = 0;                            // visited in the insertion with this stamp
  glm::dvec3 normal{0.0};                            // (v1 - v0) x (v2 - v0), rounded
  double permanent = 0.0;                            // largest permanent of its 2 x 2 minors (filter bound)
};

// The exact sign of det[v1 - v0, v2 - v0, p - v0]: positive when p is strictly above the triangle.
int side_of(const Array<glm::dvec3>& q, const Triangle& t, std::uint32_t p) {
  const glm::dvec3& a = q[t.v[0]];
  const glm::dvec3 w = q[p] - a;
  const double det = glm::dot(w, t.normal);
  const double bound = orient3d_error_bound * t.permanent * (std::abs(w.x) + std::abs(w.y) + std::abs(w.z));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  if (bound == 0.0) return 0;
  return orient3d_exact(a, q[t.v[1]], q[t.v[2]], q[p]);
}

// Half-edge 3t + k of triangle t runs from v[k] to v[k + 1].
std::uint32_t next_half_edge(std::uint32_t h) { return h - h % 3 + (h % 3 + 1) % 3; }

class TriangleHull {
 public:
  explicit TriangleHull(const Array<glm::dvec3>& q) : q_(q), cone_start_(q.size(), none) {}

  // The hull of the points `subset` (increasing, so in the order of the curve): an empty string, or why
  // there is none.
  std::string build(std::span<const std::uint32_t> subset) {
    triangles_.clear();
    twin_.clear();
    free_.clear();
    triangles_.reserve(2 * subset.size() + 8);
    twin_.reserve(6 * subset.size() + 24);
    stamp_ = 0;
    std::array<std::uint32_t, 4> simplex{};
    if (std::string why = choose_simplex(subset, simplex); !why.empty()) return why;
    if (std::string why = start(simplex); !why.empty()) return why;
    for (std::uint32_t p : insertion_order(subset)) {
      if (std::find(simplex.begin(), simplex.end(), p) != simplex.end()) continue;
      const std::uint32_t t = locate(p);
      if (side(triangles_[t], p) > 0) {
        insert(p, t);
      } else {
        last_ = t;  // inside or on the hull: the next point starts here
      }
    }
    return {};
  }

  const Array<Triangle>& triangles() const { return triangles_; }
  std::uint32_t twin(std::uint32_t h) const { return twin_[h]; }
  bool alive(std::uint32_t t) const { return triangles_[t].v[0] != none; }

  int side(const Triangle& t, std::uint32_t p) const { return side_of(q_, t, p); }

  // The triangles and their half-edges' twins, which the hull gives up (build makes them again).
  Array<Triangle> release_triangles() { return std::move(triangles_); }
  Array<std::uint32_t> release_twins() { return std::move(twin_); }

 private:
  // BRIO: each point draws its round, the last round holding half of them, the one before a quarter, and
  // so on; rounds go in order, each along the curve (increasing indices). A fixed seed and
  // std::mt19937_64, whose sequence the standard fixes: the same hull everywhere.
  static Array<std::uint32_t> insertion_order(std::span<const std::uint32_t> subset) {
    constexpr int rounds = 32;
    std::mt19937_64 engine(0x9E3779B97F4A7C15ull);
    Array<std::uint8_t> round(subset.size());
    std::array<std::size_t, rounds + 1> start{};
    for (std::size_t i = 0; i < subset.size(); ++i) {
      // Trailing zeros of a random word: 0 with probability 1/2, 1 with 1/4, ...; round rounds - 1 - that.
      const int zeros = std::min(rounds - 1, std::countr_zero(engine() | (std::uint64_t(1) << 63)));
      round[i] = static_cast<std::uint8_t>(rounds - 1 - zeros);
      ++start[round[i] + 1];
    }
    for (int r = 0; r < rounds; ++r) start[r + 1] += start[r];
    Array<std::uint32_t> order(subset.size());
    for (std::size_t i = 0; i < subset.size(); ++i) order[start[round[i]]++] = subset[i];
    return order;
  }

  std::string choose_simplex(std::span<const std::uint32_t> subset, std::array<std::uint32_t, 4>& s) const {
    const std::string count = std::to_string(subset.size()) + " points";
    // Far apart in floating point, for a large first hull; each choice is then confirmed exactly.
    std::uint32_t i0 = subset[0];
    for (std::uint32_t i : subset) {
      if (q_[i].x < q_[i0].x) i0 = i;
    }
    std::uint32_t i1 = none;
    double best = 0.0;
    for (std::uint32_t i : subset) {
      const glm::dvec3 d = q_[i] - q_[i0];
      if (glm::dot(d, d) > best) best = glm::dot(d, d), i1 = i;
    }
    if (i1 == none) return "all " + count + " coincide";
    std::uint32_t i2 = none;
    best = 0.0;
    for (std::uint32_t i : subset) {
      const glm::dvec3 c = glm::cross(q_[i1] - q_[i0], q_[i] - q_[i0]);
      if (glm::dot(c, c) > best) best = glm::dot(c, c), i2 = i;
    }
    if (i2 == none || collinear(q_[i0], q_[i1], q_[i2])) {
      i2 = none;
      for (std::uint32_t i : subset) {
        if (!collinear(q_[i0], q_[i1], q_[i])) {
          i2 = i;
          break;
        }
      }
    }
    if (i2 == none) return "all " + count + " lie on one line";
    const glm::dvec3 normal = glm::cross(q_[i1] - q_[i0], q_[i2] - q_[i0]);
    std::uint32_t i3 = none;
    best = 0.0;
    for (std::uint32_t i : subset) {
      const double d = std::abs(glm::dot(q_[i] - q_[i0], normal));
      if (d > best) best = d, i3 = i;
    }
    if (i3 == none || orient3d(q_[i0], q_[i1], q_[i2], q_[i3]) == 0) {
      i3 = none;
      for (std::uint32_t i : subset) {
        if (orient3d(q_[i0], q_[i1], q_[i2], q_[i]) != 0) {
          i3 = i;
          break;
        }
      }
    }
    if (i3 == none) return "all " + count + " lie in one plane";
    s = {i0, i1, i2, i3};
    return {};
  }

  // The tetrahedron, its triangles counter-clockwise seen from outside, and the centre the walks see the
  // hull from: the tetrahedron's centroid, which must lie strictly inside it (it does unless the points
  // are coplanar to rounding).
  std::string start(std::array<std::uint32_t, 4> s) {
    if (orient3d(q_[s[0]], q_[s[1]], q_[s[2]], q_[s[3]]) < 0) std::swap(s[1], s[2]);
    const auto [a, b, c, d] = s;  // d above a, b, c
    make_triangle(a, c, b);
    make_triangle(a, b, d);
    make_triangle(b, c, d);
    make_triangle(c, a, d);
    for (std::uint32_t h = 0; h < 12; ++h) {
      for (std::uint32_t g = 0; g < 12; ++g) {
        if (from(h) == to(g) && to(h) == from(g)) twin_[h] = g;
      }
    }
    centre_ = (q_[a] + q_[b] + q_[c] + q_[d]) * 0.25;
    // Each point's offset from the centre, rounded as orient3d rounds it: the walk's tests then need one
    // cross product each.
    from_centre_.resize(q_.size());
    for (std::size_t i = 0; i < q_.size(); ++i) from_centre_[i] = q_[i] - centre_;
    for (const Triangle& t : triangles_) {
      if (orient3d(q_[t.v[0]], q_[t.v[1]], q_[t.v[2]], centre_) >= 0)
        return "the points are nearly coplanar: the centroid of the first four corners chosen is not "
               "strictly inside them";
    }
    last_ = 0;
    return {};
  }

  std::uint32_t from(std::uint32_t h) const { return triangles_[h / 3].v[h % 3]; }
  std::uint32_t to(std::uint32_t h) const { return triangles_[h / 3].v[(h % 3 + 1) % 3]; }

  std::uint32_t make_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
    } else {
      id = static_cast<std::uint32_t>(triangles_.size());
      triangles_.emplace_back();
      twin_.resize(twin_.size() + 3, none);
    }
    Triangle& t = triangles_[id];
    t.v = {a, b, c};
    const glm::dvec3 u = q_[b] - q_[a], v = q_[c] - q_[a];
    t.normal = {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
    t.permanent =
        std::max({std::abs(u.y * v.z) + std::abs(u.z * v.y), std::abs(u.z * v.x) + std::abs(u.x * v.z),
                  std::abs(u.x * v.y) + std::abs(u.y * v.x)});
    t.mark = 0;
    return id;
  }

  // True if p lies in the closed cone from the centre over triangle t's edge k: on the inner side of the
  // plane through the centre and the edge.
  bool within_edge(const Triangle& t, std::uint32_t k, std::uint32_t p) const {
    const std::uint32_t a = t.v[k], b = t.v[(k + 1) % 3];
    const int sign = orient3d_filter(from_centre_[a], from_centre_[b], from_centre_[p]);
    return (sign != 2 ? sign : orient3d_exact(centre_, q_[a], q_[b], q_[p])) >= 0;
  }

  // A triangle whose cone from the centre holds p, found by walking across the edges p lies beyond, from
  // the last triangle made or found (Devillers, Pion and Teillaud's stochastic visibility walk: the edge
  // tried first is random, so that the walk cannot cycle). Seen from the centre, the triangles tile the
  // sphere of directions, so the walk ends; after very many steps it gives way to a search of all of them.
  std::uint32_t locate(std::uint32_t p) {
    std::uint32_t t = last_, came = 3;  // the edge the walk came in by, which p is within
    const std::size_t limit = 4 * triangles_.size() + 64;
    for (std::size_t step = 0; step < limit; ++step) {
      rng_ ^= rng_ << 13, rng_ ^= rng_ >> 7, rng_ ^= rng_ << 17;
      const auto first = static_cast<std::uint32_t>(rng_ % 3);
      std::uint32_t beyond = none;
      for (std::uint32_t i = 0; i < 3 && beyond == none; ++i) {
        const std::uint32_t k = (first + i) % 3;
        if (k != came && !within_edge(triangles_[t], k, p)) beyond = k;
      }
      if (beyond == none) return t;
      const std::uint32_t h = twin_[3 * t + beyond];
      t = h / 3;
      came = h % 3;
    }
    for (std::uint32_t u = 0; u < triangles_.size(); ++u) {
      if (alive(u) && within_edge(triangles_[u], 0, p) && within_edge(triangles_[u], 1, p) &&
          within_edge(triangles_[u], 2, p))
        return u;
    }
    return t;  // not reached: the cones cover every direction
  }

  // Adds p, which lies strictly above triangle t.
  void insert(std::uint32_t p, std::uint32_t t0) {
    ++stamp_;
    const std::uint32_t seen = 2 * stamp_, unseen = 2 * stamp_ + 1;
    visible_.assign(1, t0);
    triangles_[t0].mark = seen;
    horizon_.clear();
    // The faces p sees are connected: a search from one of them finds them all, and the edges where it
    // stops form the horizon, one closed loop.
    for (std::size_t i = 0; i < visible_.size(); ++i) {
      const std::uint32_t t = visible_[i];
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t h = twin_[3 * t + k];
        Triangle& u = triangles_[h / 3];
        if (u.mark == seen) continue;
        if (u.mark != unseen) {
          if (side(u, p) > 0) {
            u.mark = seen;
            visible_.push_back(h / 3);
            continue;
          }
          u.mark = unseen;
        }
        horizon_.push_back(h);
      }
    }
    for (std::uint32_t t : visible_) {
      triangles_[t].v[0] = none;
      free_.push_back(t);
    }
    // The cone: for each horizon edge a -> b (of a visible face), the triangle a, b, p.
    cone_.clear();
    for (std::uint32_t h : horizon_) {
      const std::uint32_t a = to(h), b = from(h);
      const std::uint32_t t = make_triangle(a, b, p);
      twin_[3 * t] = h;
      twin_[h] = 3 * t;
      cone_start_[a] = t;
      cone_.push_back(t);
    }
    for (std::uint32_t t : cone_) {
      const std::uint32_t after = cone_start_[triangles_[t].v[1]];  // b, c, p: its edge p -> b
      twin_[3 * t + 1] = 3 * after + 2;
      twin_[3 * after + 2] = 3 * t + 1;
    }
    last_ = cone_[0];
  }

  const Array<glm::dvec3>& q_;
  Array<Triangle> triangles_;
  Array<std::uint32_t> twin_;
  Array<std::uint32_t> free_;
  Array<std::uint32_t> cone_start_;  // per point: the cone triangle whose first edge starts there
  Array<std::uint32_t> visible_, horizon_, cone_;
  glm::dvec3 centre_{0.0};
  Array<glm::dvec3> from_centre_;
  std::uint32_t last_ = 0;
  std::uint32_t stamp_ = 0;
  std::uint64_t rng_ = 0x2545F4914F6CDD1Dull;
};

// ---- stage 2 ---------------------------------------------------------------------------------------------

// The faces, over the triangles of stage 1: a face is a set of triangles (a region), named by its smallest
// triangle, its root, which keeps the face's unit normal (in `normal`) and its number of sides (in `mark`).
// Its corners are slots: the half-edges on its boundary, linked along it by `next` and `prev`; `twin` pairs
// each slot with the slot of the face across its edge.
struct Faces {
  Array<Triangle> triangles;
  Array<std::uint32_t> twin;        // per half-edge
  Array<std::uint32_t> region;      // per triangle: its face's root
  Array<std::uint32_t> next, prev;  // per half-edge: along the face, for slots (none otherwise)
  Array<std::uint32_t> first;       // per root: a slot of the face
  Array<char> merged;               // per root: more than one triangle, or a vertex taken out
  Array<std::uint32_t> roots;       // the faces, increasing

  std::uint32_t vertex(std::uint32_t s) const { return triangles[s / 3].v[s % 3]; }
  std::uint32_t face(std::uint32_t s) const { return region[s / 3]; }
  const glm::dvec3& normal(std::uint32_t f) const { return triangles[f].normal; }
  std::uint32_t& size(std::uint32_t f) { return triangles[f].mark; }
  std::uint32_t size(std::uint32_t f) const { return triangles[f].mark; }
  template <class F>
  void for_each_slot(std::uint32_t f, F&& visit) const {
    std::uint32_t s = first[f];
    do {
      visit(s);
      s = next[s];
    } while (s != first[f]);
  }
};

// Union-find over the triangles; a set's root is its smallest member.
void unite(Array<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  a = find(a), b = find(b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

// The unit Newell normal of face f, and the largest distance of a corner from the plane through the
// corners' centroid.
std::pair<glm::dvec3, double> newell_plane(const Faces& faces, std::uint32_t f, const Array<glm::dvec3>& q) {
  glm::dvec3 newell(0.0), centroid(0.0);
  faces.for_each_slot(f, [&](std::uint32_t s) {
    newell += glm::cross(q[faces.vertex(s)], q[faces.vertex(faces.next[s])]);
    centroid += q[faces.vertex(s)];
  });
  const glm::dvec3 normal = glm::normalize(newell);
  centroid /= double(faces.size(f));
  double off = 0.0;
  faces.for_each_slot(f, [&](std::uint32_t s) {
    off = std::max(off, std::abs(glm::dot(q[faces.vertex(s)] - centroid, normal)));
  });
  return {normal, off};
}

// The faces of the triangle hull: an empty string, or why they cannot be made.
std::string merge_triangles(TriangleHull& hull, const Array<glm::dvec3>& q, double diagonal, Faces& out) {
  out.triangles = hull.release_triangles();
  out.twin = hull.release_twins();
  const Array<Triangle>& tris = out.triangles;
  const auto n = static_cast<std::uint32_t>(tris.size());
  auto alive = [&](std::uint32_t t) { return tris[t].v[0] != none; };
  const double tan_angle = std::tan(hull_angle_tolerance);
  Array<std::uint32_t>& region = out.region;
  region.resize(n);
  for (std::uint32_t t = 0; t < n; ++t) region[t] = t;
  bool any = false;
  for (std::uint32_t t = 0; t < n; ++t) {
    if (!alive(t)) continue;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t h = 3 * t + k, o = out.twin[h];
      if (o < h) continue;
      const Triangle& u = tris[o / 3];
      if (within_angle(tris[t].normal, u.normal, tan_angle) ||
          side_of(q, tris[t], u.v[(o % 3 + 2) % 3]) == 0) {
        unite(region, t, o / 3);
        any = true;
      }
    }
  }
  out.merged.assign(n, 0);
  for (std::uint32_t t = 0; t < n; ++t) {
    region[t] = region[region[t]];  // roots come first, so one step reaches them
    if (any && region[t] != t) out.merged[region[t]] = 1;
  }
  // Each region's boundary, walked from its first boundary half-edge: the next one leaves the end vertex,
  // found by turning about it through the region's triangles.
  out.next.assign(3 * std::size_t(n), none);
  out.prev.assign(3 * std::size_t(n), none);
  out.first.assign(n, none);
  Array<std::uint32_t> visit(any ? q.size() : 0, none);
  for (std::uint32_t t = 0; t < n; ++t) {
    if (!alive(t)) continue;
    const std::uint32_t f = region[t];
    if (!out.merged[f]) {  // a face of one triangle: its half-edges as they are
      for (std::uint32_t k = 0; k < 3; ++k) {
        out.next[3 * t + k] = next_half_edge(3 * t + k);
        out.prev[next_half_edge(3 * t + k)] = 3 * t + k;
      }
      out.first[f] = 3 * t;
      out.size(f) = 3;
      out.roots.push_back(f);
      continue;
    }
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t start = 3 * t + k;
      if (out.next[start] != none || region[out.twin[start] / 3] == f) continue;
      if (out.first[f] != none) return "a nearly flat part of the hull is not a disk";
      out.first[f] = start;
      out.roots.push_back(f);  // in increasing order: a face is met first at its smallest triangle
      std::uint32_t h = start, sides = 0;
      do {
        if (any) {
          if (visit[out.vertex(h)] == f) return "a nearly flat part of the hull touches itself at a vertex";
          visit[out.vertex(h)] = f;
        }
        std::uint32_t g = next_half_edge(h);
        while (region[out.twin[g] / 3] == f) g = next_half_edge(out.twin[g]);
        out.next[h] = g;
        out.prev[g] = h;
        h = g;
        ++sides;
      } while (h != start);
      out.size(f) = sides;
    }
  }
  for (std::uint32_t f : out.roots) {
    if (!out.merged[f]) {
      out.triangles[f].normal = glm::normalize(out.triangles[f].normal);
      continue;
    }
    const auto [normal, off] = newell_plane(out, f, q);
    out.triangles[f].normal = normal;
    if (off > hull_planarity_tolerance * diagonal) {
      return "faces meeting at less than " + format_number(hull_angle_tolerance) +
             " radians would make a face " + format_number(off / diagonal) +
             " of the diagonal off its plane (more than " + format_number(hull_planarity_tolerance) + ")";
    }
  }
  return {};
}

// ---- stage 3 ---------------------------------------------------------------------------------------------

// Takes the vertices at which a face turns by at most the angle tolerance out of the faces where they lie
// on the edge between two faces; returns those that need the hull built again without them.
Array<std::uint32_t> straighten(Faces& faces, const Array<glm::dvec3>& q) {
  const double tan_angle = std::tan(hull_angle_tolerance);
  Array<char> dropped(q.size(), 0);
  Array<std::uint32_t> rebuild, work;
  auto examine = [&](std::uint32_t s) {
    const std::uint32_t v = faces.vertex(s);
    if (faces.next[s] == none || dropped[v]) return;  // taken out, or to be
    const glm::dvec3& p = q[v];
    if (turns_left(p - q[faces.vertex(faces.prev[s])], q[faces.vertex(faces.next[s])] - p,
                   faces.normal(faces.face(s)), tan_angle))
      return;
    // On the edge between two faces exactly when the face across its incoming edge runs along its
    // outgoing one too: F runs u -> v -> w and G runs w -> v -> u.
    const std::uint32_t u_in_f = faces.prev[s], w_in_g = faces.twin[s];
    const std::uint32_t v_in_g = faces.next[w_in_g];
    const std::uint32_t f = faces.face(s), g = faces.face(w_in_g);
    if (faces.twin[u_in_f] != v_in_g || faces.size(f) <= 3 || faces.size(g) <= 3) {
      dropped[v] = 1;
      rebuild.push_back(v);
      return;
    }
    // Both lose v; F's u -> w and G's w -> u pair up.
    for (std::uint32_t r : {s, v_in_g}) {
      const std::uint32_t face = faces.face(r);
      faces.next[faces.prev[r]] = faces.next[r];
      faces.prev[faces.next[r]] = faces.prev[r];
      if (faces.first[face] == r) faces.first[face] = faces.next[r];
      --faces.size(face);
      faces.merged[face] = 1;
      work.push_back(faces.prev[r]);
      work.push_back(faces.next[r]);
      faces.next[r] = faces.prev[r] = none;
    }
    faces.twin[u_in_f] = w_in_g;
    faces.twin[w_in_g] = u_in_f;
  };
  for (std::uint32_t f : faces.roots) {
    if (faces.merged[f]) {
      faces.for_each_slot(f, [&](std::uint32_t s) { work.push_back(s); });
    } else {
      // A triangle: its three corners from its three points, and only a corner that fails looked at again.
      const std::array<std::uint32_t, 3>& v = faces.triangles[f].v;
      const glm::dvec3 edge[3] = {q[v[1]] - q[v[0]], q[v[2]] - q[v[1]], q[v[0]] - q[v[2]]};
      for (std::uint32_t k = 0; k < 3; ++k) {
        if (!turns_left(edge[(k + 2) % 3], edge[k], faces.normal(f), tan_angle)) work.push_back(3 * f + k);
      }
    }
    while (!work.empty()) {
      const std::uint32_t r = work.back();
      work.pop_back();
      examine(r);
    }
  }
  return rebuild;
}

// The vertices left in the faces, in increasing order, without those of `without`.
Array<std::uint32_t> face_vertices(const Faces& faces, std::size_t num_points,
                                   std::span<const std::uint32_t> without) {
  Array<char> in(num_points, 0);
  for (std::uint32_t f : faces.roots)
    faces.for_each_slot(f, [&](std::uint32_t s) { in[faces.vertex(s)] = 1; });
  for (std::uint32_t v : without) in[v] = 0;
  Array<std::uint32_t> out;
  for (std::uint32_t i = 0; i < num_points; ++i) {
    if (in[i]) out.push_back(i);
  }
  return out;
}

// ---- stage 4 ---------------------------------------------------------------------------------------------

// What the convexity check would refuse in the result that the stages above have not already excluded,
// checked with half the working tolerances: a centroid too close to a face plane (refused as nearly
// coplanar), and a merged face too close to coplanar with a neighbour once its normal is the merged one.
// (Turns were checked with the full tolerance by `straighten`, triangles' normals by `merge_triangles`.)
std::string verify(const Faces& faces, const Array<glm::dvec3>& q, const Array<std::uint32_t>& vertices,
                   double diagonal) {
  glm::dvec3 centre(0.0);
  for (std::uint32_t v : vertices) centre += q[v] / double(vertices.size());
  double depth = std::numeric_limits<double>::max();
  for (std::uint32_t f : faces.roots) {
    depth = std::min(depth, glm::dot(q[faces.vertex(faces.first[f])] - centre, faces.normal(f)));
  }
  if (!(depth > hull_flatness_tolerance * diagonal)) {
    return "the points are nearly coplanar: the centroid of their hull's vertices lies " +
           format_number(depth / diagonal) + " of the diagonal inside a face's plane (at most " +
           format_number(hull_flatness_tolerance) + " is refused)";
  }
  const double tan_angle = std::tan(verified_angle);
  bool flat = false;
  for (std::uint32_t f : faces.roots) {
    if (!faces.merged[f]) continue;
    faces.for_each_slot(f, [&](std::uint32_t s) {
      flat = flat || within_angle(faces.normal(f), faces.normal(faces.face(faces.twin[s])), tan_angle);
    });
  }
  if (flat) {
    return "the points are too close to a degenerate configuration: two faces of their hull meet at less "
           "than " +
           format_number(verified_angle) + " radians";
  }
  return {};
}

}  // namespace

HullOutcome hull_of_points(std::span<const glm::dvec3> points, const NameOf& name_of) {
  HullOutcome out;
  if (points.size() < 4) {
    out.refusal = "only " + std::to_string(points.size()) +
                  " points: a hull needs at least 4 points that do not lie in one plane";
    return out;
  }
  if (points.size() >= none / 8) {
    out.refusal = std::to_string(points.size()) + " points are more than 32-bit handles can number";
    return out;
  }
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i])) {
      out.refusal = name_of(i) + " is not finite";
      return out;
    }
  }
  // The points renumbered along the curve: point i of q is points[original[i]].
  Array<glm::dvec3> q = scaled_points(points);
  const Array<std::uint32_t> original = curve_order(q);
  {
    Array<glm::dvec3> sorted(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) sorted[i] = q[original[i]];
    q = std::move(sorted);
  }
  Array<std::uint32_t> subset(q.size());
  for (std::uint32_t i = 0; i < subset.size(); ++i) subset[i] = i;
  const double diagonal = box_diagonal(q);
  TriangleHull hull(q);
  Faces faces;
  for (int round = 0;; ++round) {
    if (round == max_rounds) {
      out.refusal = "the points are too close to a degenerate configuration: " + std::to_string(max_rounds) +
                    " rounds did not leave every face turning by more than " +
                    format_number(hull_angle_tolerance) + " radians at every corner";
      return out;
    }
    if (std::string why = hull.build(subset); !why.empty()) {
      out.refusal = why + ": they have no hull of positive volume";
      return out;
    }
    faces = Faces{};
    if (std::string why = merge_triangles(hull, q, diagonal, faces); !why.empty()) {
      out.refusal = "the points are too close to a degenerate configuration: " + why;
      return out;
    }
    const Array<std::uint32_t> rebuild = straighten(faces, q);
    if (rebuild.empty()) break;
    subset = face_vertices(faces, q.size(), rebuild);
  }

  const Array<std::uint32_t> kept = face_vertices(faces, q.size(), {});
  if (std::string why = verify(faces, q, kept, diagonal); !why.empty()) {
    out.refusal = why;
    return out;
  }
  // Vertices in increasing order of their original index, at the points' own positions.
  Array<std::uint32_t> vertex_of_point(points.size(), none);
  for (std::uint32_t v : kept) vertex_of_point[original[v]] = 0;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    if (vertex_of_point[i] == none) continue;
    vertex_of_point[i] = static_cast<std::uint32_t>(out.hull.source.size());
    out.hull.source.push_back(i);
  }
  // Corners face by face (their numbers kept in `prev`, free now); a corner's twin is that of its slot.
  Array<std::uint32_t> offsets{0}, slots;
  slots.reserve(faces.next.size());
  for (std::uint32_t f : faces.roots) {
    faces.for_each_slot(f, [&](std::uint32_t s) {
      faces.prev[s] = static_cast<std::uint32_t>(slots.size());
      slots.push_back(s);
    });
    offsets.push_back(static_cast<std::uint32_t>(slots.size()));
  }
  MeshAssembler assembler(out.hull.source.size(), offsets);
  for (std::uint32_t i = 0; i < out.hull.source.size(); ++i)
    assembler.set_position(i, points[out.hull.source[i]]);
  Array<std::uint32_t> vertex_of(q.size(), none);  // per point of q
  for (std::uint32_t v : kept) vertex_of[v] = vertex_of_point[original[v]];
  for (std::uint32_t k = 0; k < slots.size(); ++k) {
    const std::uint32_t s = slots[k];
    assembler.set_corner(k, vertex_of[faces.vertex(s)], faces.prev[faces.twin[s]]);
  }
  out.hull.mesh = assembler.finish();
  return out;
}

namespace {

HullMesh hull_or_refuse(std::span<const glm::dvec3> points, std::string_view op, std::string_view parameter,
                        const NameOf& name_of) {
  HullOutcome outcome = hull_of_points(points, name_of);
  if (!outcome.refusal.empty()) refuse(op, parameter, outcome.refusal);
  return std::move(outcome.hull);
}

}  // namespace

HullMesh hull_of_point_set(std::span<const glm::dvec3> points, std::string_view op) {
  return hull_or_refuse(points, op, "points", [](std::uint32_t i) { return "point " + std::to_string(i); });
}

HullMesh hull_of_mesh(const Mesh& mesh, std::string_view op) {
  std::vector<glm::dvec3> points;
  std::vector<VertexId> vertex;
  points.reserve(mesh.num_vertices());
  vertex.reserve(mesh.num_vertices());
  for (VertexId v : mesh.vertices()) {
    points.push_back(mesh.position(v));
    vertex.push_back(v);
  }
  HullMesh hull = hull_or_refuse(points, op, "mesh", [&](std::uint32_t i) { return to_string(vertex[i]); });
  for (std::uint32_t& s : hull.source) s = vertex[s].index();
  return hull;
}

OperationSpec hull_operation(std::string name, std::string doc, Mesh (*build)(const Mesh&)) {
  return replace_operation(std::move(name), std::move(doc), {},
                           [build](const Mesh& current, const Params&) { return build(current); });
}

void declare_attributes(const Mesh& from, Mesh& to) {
  for (const AttributeInfo& a : from.attributes()) to.add_attribute(a.kind, a.name, a.default_value);
}

}  // namespace dlfl::detail

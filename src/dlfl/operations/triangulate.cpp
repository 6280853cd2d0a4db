// triangulate: see triangulate.h. Ear clipping on the face's corners projected into its plane; each ear cut
// off is one insert_edge between the ear's two neighbours, which splits the triangle off the face.

#include <dlfl/operations/triangulate.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <string>
#include <utility>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// A face's corners in its plane, as a circular list that loses a node with each ear cut off.
class PlanarPolygon {
 public:
  PlanarPolygon(const Mesh& m, FaceId f) {
    // (u, w, normal) is right-handed, so the face, counter-clockwise about its normal, is counter-clockwise
    // in (u, w) too.
    glm::dvec3 normal = face_normal(m, f);
    if (normal == glm::dvec3(0.0)) normal = glm::dvec3(0, 0, 1);  // degenerate: any plane will do
    const glm::dvec3 a = glm::abs(normal);
    const glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                            : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                                     : glm::dvec3(0, 0, 1);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, normal));
    const glm::dvec3 w = glm::cross(normal, u);
    const glm::dvec3 origin = m.position(m.vertex(m.first_corner(f)));
    for (CornerId c : m.corners(f)) {
      const glm::dvec3 d = m.position(m.vertex(c)) - origin;
      corner.push_back(c);
      vertex.push_back(m.vertex(c));
      point.emplace_back(glm::dot(d, u), glm::dot(d, w));
    }
    const auto n = static_cast<std::uint32_t>(corner.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      prev.push_back((i + n - 1) % n);
      next.push_back((i + 1) % n);
    }
    remaining = n;
  }

  // Twice the signed area of the triangle prev(i), i, next(i): positive where the polygon turns left.
  double turn(std::uint32_t i) const {
    const glm::dvec2& p = point[prev[i]];
    return cross(point[i] - p, point[next[i]] - p);
  }

  // The diagonal between i's neighbours exists (no self-loop) and lies inside the polygon.
  bool cuttable(std::uint32_t i) const { return vertex[prev[i]] != vertex[next[i]]; }

  // How many of i's two neighbours could still be cut off once i is (both, when a triangle is left).
  int neighbours_left_cuttable(std::uint32_t i) const {
    if (remaining <= 4) return 2;
    const std::uint32_t a = prev[i], b = next[i];
    return int(vertex[prev[a]] != vertex[b]) + int(vertex[a] != vertex[next[b]]);
  }

  bool is_ear(std::uint32_t i) const {
    if (!cuttable(i) || turn(i) <= 0.0) return false;
    const std::uint32_t a = prev[i], b = next[i];
    for (std::uint32_t j = next[b]; j != a; j = next[j]) {
      if (inside_triangle(point[j], point[a], point[i], point[b])) return false;
    }
    return true;
  }

  std::vector<CornerId> corner;  // per node; the left neighbour of a cut ear gets the diagonal's corner
  std::vector<VertexId> vertex;
  std::vector<glm::dvec2> point;
  std::vector<std::uint32_t> prev, next;
  std::uint32_t remaining = 0;

 private:
  // In the closed triangle a, b, c (counter-clockwise) but not one of its corners: a corner there would
  // make the cut cross or touch the polygon's boundary.
  static bool inside_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b,
                              const glm::dvec2& c) {
    if (p == a || p == b || p == c) return false;
    return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
  }
};

// The node to cut off next, or `none`: an ear if there is one, else the most convex cuttable corner; among
// those, one that leaves its neighbours cuttable where it can, since a face that visits a vertex more than
// once can otherwise be left with corners that no diagonal can cut off (a, b, a, b).
std::uint32_t next_tip(const PlanarPolygon& poly, std::vector<char>& ear, std::uint32_t from) {
  for (int pass = 0; pass < 2; ++pass) {
    std::uint32_t best = none;
    int best_left = -1;
    std::uint32_t j = from;
    for (std::uint32_t k = 0; k < poly.remaining; ++k, j = poly.next[j]) {
      if (!ear[j]) continue;
      const int left = poly.neighbours_left_cuttable(j);
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
    for (std::uint32_t k = 0; k < poly.remaining; ++k, j = poly.next[j]) ear[j] = poly.is_ear(j);
  }
  std::uint32_t best = none;
  std::pair<int, double> best_rank(-1, -std::numeric_limits<double>::infinity());
  std::uint32_t j = from;
  for (std::uint32_t k = 0; k < poly.remaining; ++k, j = poly.next[j]) {
    const std::pair<int, double> rank(poly.neighbours_left_cuttable(j), poly.turn(j));
    if (poly.cuttable(j) && rank > best_rank) {
      best = j;
      best_rank = rank;
    }
  }
  return best;
}

// Cuts f into triangles; returns one corner of each of the faces f became.
void triangulate_face(Transaction& tx, FaceId f, std::vector<CornerId>& pieces) {
  const Mesh& m = tx.mesh();
  PlanarPolygon poly(m, f);
  std::vector<char> ear(poly.corner.size());
  for (std::uint32_t i = 0; i < poly.remaining; ++i) ear[i] = poly.is_ear(i);
  std::uint32_t at = 0;
  while (poly.remaining > 3) {
    const std::uint32_t tip = next_tip(poly, ear, at);
    if (tip == none) break;
    const std::uint32_t a = poly.prev[tip], b = poly.next[tip];
    // The part of corner a is a, tip, and a new corner at b: the triangle. The rest starts with the new
    // edge's corner at a, which stands for a from now on.
    const InsertEdgeResult cut = tx.insert_edge(poly.corner[a], poly.corner[b]);
    pieces.push_back(poly.corner[tip]);
    poly.corner[a] = m.corner(cut.edge, 0);
    poly.next[a] = b;
    poly.prev[b] = a;
    --poly.remaining;
    ear[a] = poly.is_ear(a);
    ear[b] = poly.is_ear(b);
    at = b;
  }
  pieces.push_back(poly.corner[at]);
}

}  // namespace

void check_triangulate(const Mesh& m, std::span<const FaceId> faces) {
  for (FaceId f : faces) {
    if (!m.is_alive(f)) {
      throw ParameterError("triangulate: parameter faces has " + to_string(f) +
                               ", which does not exist (removed or never created)",
                           "faces");
    }
  }
  std::vector<FaceId> sorted(faces.begin(), faces.end());
  std::sort(sorted.begin(), sorted.end(), [](FaceId a, FaceId b) { return a.index() < b.index(); });
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) {
    throw ParameterError("triangulate: parameter faces lists " + to_string(*twice) + " twice", "faces");
  }
}

TriangulateResult triangulate(Transaction& tx, std::span<const FaceId> faces) {
  check_triangulate(tx.mesh(), faces);
  std::vector<CornerId> pieces;
  for (FaceId f : faces) {
    if (tx.mesh().is_hole(f) || tx.mesh().size(f) <= 3) continue;
    triangulate_face(tx, f, pieces);
  }
  TriangulateResult result;
  result.faces.reserve(pieces.size());
  // A triangle, once cut off, is not touched again: its corner still names it.
  for (CornerId c : pieces) result.faces.push_back(tx.mesh().face(c));
  return result;
}

TriangulateResult triangulate_all(Transaction& tx) {
  std::vector<FaceId> faces;
  for (FaceId f : tx.mesh().faces()) faces.push_back(f);
  return triangulate(tx, faces);
}

std::vector<OperationSpec> detail::triangulate_operation_specs() {
  return {edit_operation(
      "triangulate",
      "cuts faces into triangles by diagonals (ear clipping in the face's plane); holes and triangles stay",
      {param("faces", ParamType::faces, "the faces to triangulate").optional("every face")},
      "E+(n-3), F+(n-3) per face of n > 3 sides",
      [](Transaction& tx, const Params& p) {
        const TriangulateResult r =
            p.has("faces") ? triangulate(tx, p.handles<FaceId>("faces")) : triangulate_all(tx);
        return Params{{"faces", r.faces}};
      },
      [](const Mesh& m, Params& p) {
        if (p.has("faces")) check_triangulate(m, p.handles<FaceId>("faces"));
      })};
}
}  // namespace dlfl

// convex_hull agrees with CGAL's convex_hull_3 (an independent implementation, with exact predicates): the
// same corners, and as many faces as CGAL's triangles make once the coplanar ones across an edge are merged
// (decided by CGAL's exact coplanarity predicate).

#include <doctest/doctest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include <dlfl/operations/convex_hull.h>

using namespace dlfl;

namespace {

using Exact = CGAL::Exact_predicates_inexact_constructions_kernel;
using HullMesh = CGAL::Surface_mesh<Exact::Point_3>;
using Key = std::tuple<double, double, double>;

struct CgalHull {
  std::set<Key> corners;
  std::size_t faces = 0;  // after merging coplanar neighbours
};

CgalHull cgal_hull(const std::vector<glm::dvec3>& points) {
  std::vector<Exact::Point_3> p;
  for (const glm::dvec3& q : points) p.emplace_back(q.x, q.y, q.z);
  HullMesh sm;
  CGAL::convex_hull_3(p.begin(), p.end(), sm);
  CgalHull out;
  for (auto v : sm.vertices()) {
    const auto& q = sm.point(v);
    out.corners.insert({q.x(), q.y(), q.z()});
  }
  // Faces of coplanar triangles: union-find over CGAL's faces across every edge whose four points are
  // coplanar.
  std::vector<std::size_t> parent(sm.number_of_faces());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (auto e : sm.edges()) {
    const auto h = sm.halfedge(e), o = sm.opposite(h);
    const auto a = sm.point(sm.source(h)), b = sm.point(sm.target(h));
    const auto c = sm.point(sm.target(sm.next(h))), d = sm.point(sm.target(sm.next(o)));
    if (CGAL::coplanar(a, b, c, d)) parent[find(sm.face(h).idx())] = find(sm.face(o).idx());
  }
  for (std::size_t f = 0; f < parent.size(); ++f) out.faces += find(f) == f ? 1 : 0;
  return out;
}

std::vector<glm::dvec3> random_points(std::size_t n, int kind, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g;
  std::uniform_int_distribution<int> small(-3, 3);
  std::vector<glm::dvec3> out;
  while (out.size() < n) {
    if (kind == 0) {  // in a ball
      const glm::dvec3 p(u(rng), u(rng), u(rng));
      if (glm::dot(p, p) <= 1.0) out.push_back(p);
    } else if (kind == 1) {  // on a sphere
      out.push_back(glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))));
    } else if (kind == 2) {  // a small lattice: coplanar faces, points on edges, repeats
      out.push_back(glm::dvec3(small(rng), small(rng), small(rng)));
    } else {  // the cube's surface, with its corners
      glm::dvec3 p(u(rng), u(rng), u(rng));
      p[rng() % 3] = rng() % 2 ? 1.0 : -1.0;
      if (out.size() < 8)
        p = {out.size() & 1 ? 1.0 : -1.0, out.size() & 2 ? 1.0 : -1.0, out.size() & 4 ? 1.0 : -1.0};
      out.push_back(p);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("oracle: convex_hull agrees with CGAL's convex_hull_3") {
  for (int kind = 0; kind < 4; ++kind) {
    for (std::size_t n : {10u, 100u, 2000u}) {
      CAPTURE(kind);
      CAPTURE(n);
      const std::vector<glm::dvec3> points = random_points(n, kind, 17 + n);
      const Mesh ours = convex_hull(points);
      const CgalHull theirs = cgal_hull(points);
      std::set<Key> corners;
      for (VertexId v : ours.vertices()) {
        const glm::dvec3 p = ours.position(v);
        corners.insert({p.x, p.y, p.z});
      }
      CHECK(corners == theirs.corners);
      CHECK(ours.num_faces() == theirs.faces);
    }
  }
}

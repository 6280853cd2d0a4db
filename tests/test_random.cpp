// Hundreds of thousands of random legal operators, validated as they go, and undone exactly.

#include <doctest/doctest.h>

#include <random>
#include <vector>

#include <dlfl/validate.h>
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

// Picks random live elements by rejection; the meshes here stay small and mostly alive, and are compacted
// when the tombstones pile up.
class RandomEditor {
 public:
  RandomEditor(Mesh& m, std::uint64_t seed) : m_(m), rng_(seed) {}

  template <class H>
  H pick(std::uint32_t capacity) {
    if (capacity == 0) return H();
    for (int tries = 0; tries < 64; ++tries) {
      H h(std::uniform_int_distribution<std::uint32_t>(0, capacity - 1)(rng_));
      if (m_.is_alive(h)) return h;
    }
    return H();
  }

  glm::dvec3 point() {
    std::uniform_real_distribution<double> u(-1, 1);
    return {u(rng_), u(rng_), u(rng_)};
  }

  // One random operator that is legal now, as a step; returns false if none was found this time.
  bool random_step(Step& step) {
    const int kind = std::uniform_int_distribution<int>(0, 99)(rng_);
    // Grow while small, shrink while large, so the mesh size wanders around a few hundred elements.
    const bool big = m_.num_edges() > 400;
    if ((kind < 5 && m_.num_vertices() < 300) || m_.num_vertices() < 4) {
      step = {Step::Kind::create_vertex};
      step.position = point();
      return true;
    }
    if (kind < 55 && !big) {
      CornerId a = pick<CornerId>(m_.corner_capacity()), b;
      if (!a.valid()) return false;
      if (kind % 2 == 0) {
        // A corner of the same face a few steps on: a split.
        b = a;
        for (int k = std::uniform_int_distribution<int>(1, 6)(rng_); k > 0; --k) b = m_.next(b);
      } else {
        b = pick<CornerId>(m_.corner_capacity());  // usually another face: a merge
      }
      if (!b.valid() || m_.vertex(a) == m_.vertex(b)) return false;
      step = {Step::Kind::insert_edge};
      step.corner1 = a;
      step.corner2 = b;
      return true;
    }
    if (kind < 75) {
      EdgeId e = pick<EdgeId>(m_.edge_capacity());
      if (!e.valid()) return false;
      step = {Step::Kind::delete_edge};
      step.edge = e;
      return true;
    }
    if (kind < 85) {
      VertexId v = pick<VertexId>(m_.vertex_capacity());
      if (!v.valid() || !m_.is_point_sphere(v)) return false;
      step = {Step::Kind::delete_vertex};
      step.vertex = v;
      return true;
    }
    if (kind < 92 && !big) {
      EdgeId e = pick<EdgeId>(m_.edge_capacity());
      if (!e.valid()) return false;
      step = {Step::Kind::subdivide_edge};
      step.edge = e;
      step.position = point();
      return true;
    }
    VertexId v = pick<VertexId>(m_.vertex_capacity());
    if (!v.valid()) return false;
    if (kind < 96) {
      step = {Step::Kind::set_position};
      step.vertex = v;
      step.position = point();
      return true;
    }
    // unsubdivide_edge needs a 2-valent vertex whose edges continue each other and whose neighbours differ.
    if (m_.valence(v) != 2) return false;
    CornerId a = m_.corner(v), b = m_.next_around_vertex(a);
    if ((m_.corner(m_.edge(a), 0) == a) == (m_.corner(m_.edge(b), 0) == b)) return false;
    if (m_.vertex(m_.next(a)) == m_.vertex(m_.next(b))) return false;
    step = {Step::Kind::unsubdivide_edge};
    step.vertex = v;
    return true;
  }

  std::mt19937_64& rng() { return rng_; }

 private:
  Mesh& m_;
  std::mt19937_64 rng_;
};

}  // namespace

TEST_CASE("random: 300000 random operators keep the mesh valid") {
  Mesh m = build_mesh(test::torus_soup(6, 5));
  RandomEditor ed(m, 12345);
  std::size_t applied = 0, splits = 0, merges = 0;
  while (applied < 300000) {
    Step s;
    if (!ed.random_step(s)) continue;
    if (s.kind == Step::Kind::insert_edge) {
      (m.face(s.corner1) == m.face(s.corner2) ? splits : merges) += 1;
    }
    m.apply(s);
    ++applied;
    if (applied % 2000 == 0) require_valid(m);
    if (m.corner_capacity() > 4 * m.num_corners() + 1000) m.compact();
  }
  require_valid(m);
  // Both kinds of INSERTEDGE were exercised many times.
  CHECK(splits > 10000);
  CHECK(merges > 10000);
}

TEST_CASE("random: random operators interleaved with random undo come back exactly to the start") {
  const Mesh start = build_mesh(test::genus_soup(2));
  Mesh m = start;
  RandomEditor ed(m, 777);
  std::vector<Step> undo;                               // inverses, most recent last
  std::vector<std::pair<std::size_t, Mesh>> snapshots;  // (stack depth, mesh at that depth)
  for (int round = 0; round < 200000; ++round) {
    const int dice = std::uniform_int_distribution<int>(0, 9)(ed.rng());
    if (dice < 1 && !undo.empty()) {
      // Undo a few steps; whenever we land on a snapshot's depth the mesh must equal it.
      int k = std::uniform_int_distribution<int>(1, 5)(ed.rng());
      while (k-- > 0 && !undo.empty()) {
        m.apply(undo.back());
        undo.pop_back();
        while (!snapshots.empty() && snapshots.back().first > undo.size()) snapshots.pop_back();
        if (!snapshots.empty() && snapshots.back().first == undo.size())
          REQUIRE(m == snapshots.back().second);
      }
      continue;
    }
    Step s;
    if (!ed.random_step(s)) continue;
    undo.push_back(m.apply(s));
    if (round % 5000 == 0) {
      require_valid(m);
      snapshots.emplace_back(undo.size(), m);
    }
  }
  require_valid(m);
  CHECK(undo.size() > 1000);  // the walk went far from the start
  while (!undo.empty()) {
    m.apply(undo.back());
    undo.pop_back();
  }
  CHECK(m == start);
  require_valid(m);
}

#pragma once
// The closed forms of one honeycomb step (section 2, remark 2 of the paper), shared by the tests of
// `honeycomb` and of Zhang-Wang's honeycomb, which has the same topology.

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/statistics.h>
#include <dlfl/validate.h>
#include "test_helpers.h"

namespace dlfl::test {

using Histogram = std::map<std::uint32_t, std::size_t>;

/// (Euler characteristic, genus, holes) of every component, sorted: component order may change.
inline std::vector<std::tuple<long, long, std::size_t>> topology(const Mesh& m) {
  std::vector<std::tuple<long, long, std::size_t>> t;
  for (const ComponentInfo& c : validate(m).components)
    t.emplace_back(c.euler_characteristic, c.genus, c.holes);
  std::sort(t.begin(), t.end());
  return t;
}

/// The sizes of the hole faces, sorted.
inline std::vector<std::uint32_t> hole_sizes(const Mesh& m) {
  std::vector<std::uint32_t> s;
  for (FaceId f : m.faces()) {
    if (m.is_hole(f)) s.push_back(m.size(f));
  }
  std::sort(s.begin(), s.end());
  return s;
}

/// `step(in)`, one honeycomb step of `in` (which has no point spheres), checked: the input left as it was,
/// and the closed forms: each old edge gives 2 vertices and 3 edges, each old face a front face of its size,
/// each old vertex a face of twice its valence; every new vertex has valence 3; the holes and the topology of
/// every component are kept.
template <class Step>
Mesh checked_honeycomb_step(const Mesh& in, const Step& step) {
  const Mesh copy = in;
  Mesh out = step(in);
  CHECK(in == copy);
  require_valid(out);
  const std::size_t V = in.num_vertices(), E = in.num_edges(), F = in.num_faces();
  CHECK(out.num_vertices() == 2 * E);
  CHECK(out.num_edges() == 3 * E);
  CHECK(out.num_faces() == F + V);
  const MeshStatistics s = statistics(out);
  CHECK(s.valences == Histogram{{3, 2 * E}});
  Histogram expected;
  for (FaceId f : in.faces()) {
    if (!in.is_hole(f)) ++expected[in.size(f)];
  }
  for (VertexId v : in.vertices()) ++expected[2 * in.valence(v)];
  CHECK(s.face_sizes == expected);
  CHECK(hole_sizes(out) == hole_sizes(in));
  CHECK(topology(out) == topology(in));
  return out;
}

}  // namespace dlfl::test

// Per-element containers (dlfl/mesh_data.h): sizing, lazy growth, remapping on compact, and their attachment
// through mesh copies, moves and destruction.

#include <doctest/doctest.h>

#include <memory>
#include <string>
#include <utility>

#include <dlfl/geometry.h>
#include <dlfl/mesh_data.h>
#include <dlfl/validate.h>
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

// Removes some elements of a cube: two face-splitting diagonals deleted again (tombstones in every array), a
// point sphere created and deleted, and one more kept.
Mesh cube_with_tombstones() {
  Mesh m = test::cube();
  for (FaceId f : {FaceId(0), FaceId(3)}) {
    const CornerId c = m.first_corner(f);
    m.delete_edge(m.insert_edge(c, m.next(m.next(c))).edge);
  }
  m.delete_vertex(m.create_vertex({7, 7, 7}));
  m.create_vertex({5, 6, 7});
  m.delete_edge(m.edge(m.first_corner(FaceId(1))));  // merges faces 1 and another: a face goes
  return m;
}

// The cube (vertices 0 to 7) with two more vertices, point spheres p = 8 and q = 9.
struct CubeAndTwo {
  Mesh mesh;
  VertexId p, q;
};
CubeAndTwo cube_and_two() {
  Mesh m = test::cube();
  const VertexId p = m.create_vertex({5, 5, 5});
  const VertexId q = m.create_vertex({6, 6, 6});
  return {std::move(m), p, q};
}

}  // namespace

TEST_CASE("mesh data: sized by the mesh's capacity, every element reading the default") {
  const Mesh m = test::cube();
  const VertexData<double> weight(m, 1.5);
  const EdgeData<int> edge_tag(m, -1);
  const FaceData<glm::dvec3> colour(m, glm::dvec3(0, 0, 1));
  const CornerData<bool> flag(m, true);
  CHECK(weight.size() == 8);
  CHECK(edge_tag.size() == 12);
  CHECK(colour.size() == 6);
  CHECK(flag.size() == 24);
  for (VertexId v : m.vertices()) CHECK(weight[v] == 1.5);
  for (EdgeId e : m.edges()) CHECK(edge_tag[e] == -1);
  for (FaceId f : m.faces()) CHECK(colour[f] == glm::dvec3(0, 0, 1));
  for (CornerId c : m.corners()) CHECK(flag[c]);
  CHECK(weight.attached());
  CHECK(weight.default_value() == 1.5);
  CHECK(weight.raw().size() == 8);
}

TEST_CASE("mesh data: grows as elements are added") {
  Mesh m = test::cube();
  VertexData<int> tag(m, 7);
  const VertexId a = m.create_vertex({2, 2, 2});  // handle 8
  const VertexId b = m.create_vertex({3, 3, 3});  // handle 9
  // A const access past the stored values reads the default and stores nothing.
  const VertexData<int>& read_only = tag;
  CHECK(read_only[b] == 7);
  CHECK(tag.size() == 8);
  // A write grows the storage to the mesh's capacity, so a later element is covered too.
  tag[a] = 1;
  CHECK(tag.size() == m.vertex_capacity());
  CHECK(tag[b] == 7);
  CHECK(tag[a] == 1);
  // raw() grows to the capacity as well.
  m.create_vertex({4, 4, 4});
  const std::span<int> all = tag.raw();
  REQUIRE(all.size() == 11);
  CHECK(all[8] == 1);
  CHECK(all[10] == 7);
  // A bool container is a real span of bool.
  FaceData<bool> marked(m, false);
  marked[FaceId(2)] = true;
  const std::span<bool> bits = marked.raw();
  CHECK(bits.size() == m.face_capacity());
  CHECK(bits[2]);
  CHECK_FALSE(bits[3]);
}

TEST_CASE("mesh data: values follow their elements through compact") {
  Mesh m = cube_with_tombstones();
  require_valid(m);
  REQUIRE(m.vertex_capacity() > m.num_vertices());
  REQUIRE(m.edge_capacity() > m.num_edges());
  REQUIRE(m.face_capacity() > m.num_faces());
  REQUIRE(m.corner_capacity() > m.num_corners());
  // Values that compaction cannot change: each element's own geometry.
  VertexData<glm::dvec3> where(m);
  EdgeData<glm::dvec3> midpoint(m);
  FaceData<glm::dvec3> centre(m);
  CornerData<glm::dvec3> at(m);
  for (VertexId v : m.vertices()) where[v] = m.position(v);
  for (EdgeId e : m.edges()) midpoint[e] = 0.5 * (m.position(m.from(e)) + m.position(m.to(e)));
  for (FaceId f : m.faces()) centre[f] = face_centroid(m, f);
  for (CornerId c : m.corners()) at[c] = m.position(m.vertex(c));
  // A non-trivial value type: the element's old name.
  FaceData<std::string> old_name(m, "new");
  for (FaceId f : m.faces()) old_name[f] = to_string(f);

  const Mesh::CompactMap map = m.compact();
  REQUIRE(m.face_capacity() == m.num_faces());
  CHECK(where.size() <= m.vertex_capacity());
  for (VertexId v : m.vertices()) CHECK(where[v] == m.position(v));
  for (EdgeId e : m.edges()) CHECK(midpoint[e] == 0.5 * (m.position(m.from(e)) + m.position(m.to(e))));
  for (FaceId f : m.faces()) CHECK(centre[f] == face_centroid(m, f));
  for (CornerId c : m.corners()) CHECK(at[c] == m.position(m.vertex(c)));
  for (std::uint32_t i = 0; i < map.faces.size(); ++i) {
    if (map.faces[i].valid()) CHECK(old_name[map.faces[i]] == to_string(FaceId(i)));
  }
  // Elements added after the compaction read the default again.
  const VertexId fresh = m.create_vertex({9, 9, 9});
  CHECK(std::as_const(where)[fresh] == glm::dvec3(0.0));
}

TEST_CASE("mesh data: a container outliving its mesh keeps its values") {
  auto m = std::make_unique<Mesh>(test::cube());
  VertexData<int> tag(*m, 0);
  tag[VertexId(3)] = 33;
  FaceData<double> copy_of_tag(*m, 1.0);
  m.reset();
  CHECK_FALSE(tag.attached());
  CHECK(tag[VertexId(3)] == 33);
  // Growth without a mesh: just far enough for the element.
  tag[VertexId(20)] = 1;
  CHECK(tag.size() == 21);
  CHECK(tag.raw().size() == 21);
  // Copying and moving a detached container is fine too.
  VertexData<int> copy = tag;
  VertexData<int> moved = std::move(copy);
  CHECK(moved[VertexId(3)] == 33);
  CHECK_FALSE(moved.attached());
}

TEST_CASE("mesh data: a copied mesh has no containers; a moved one takes them along") {
  auto [a, p, q] = cube_and_two();
  VertexData<int> tag(a, 0);
  tag[q] = 42;
  a.delete_vertex(p);

  Mesh b = a;  // a copy: compacting it leaves the container alone
  b.compact();
  CHECK(tag[VertexId(9)] == 42);
  CHECK(tag.attached());

  Mesh c = std::move(a);  // the container follows the data into c
  c.compact();
  CHECK(tag[VertexId(8)] == 42);
  CHECK(tag.size() == 9);

  std::swap(b, c);  // and through a swap: now the data is b's
  b.create_vertex({1, 2, 3});
  b.create_vertex({1, 2, 4});
  b.delete_vertex(VertexId(8));
  b.compact();
  CHECK(tag[VertexId(8)] == 0);  // the old q went, the next vertex moved into slot 8
  CHECK(std::as_const(tag)[VertexId(9)] == 0);

  // Assigning to the mesh replaces its data: the container detaches and keeps what it had.
  tag[VertexId(8)] = 5;
  b = Mesh(test::cube());
  CHECK_FALSE(tag.attached());
  CHECK(tag[VertexId(8)] == 5);
}

TEST_CASE("mesh data: copies and moves of a container stay attached, destroyed ones let go") {
  auto [m, p, q] = cube_and_two();
  VertexData<int> first(m, 0);
  first[q] = 1;
  VertexData<int> copy = first;
  copy[q] = 2;
  VertexData<int> assigned;
  CHECK_FALSE(assigned.attached());
  assigned = first;
  assigned[q] = 3;
  VertexData<int> moved_from(m, 0);
  moved_from[q] = 4;
  VertexData<int> moved = std::move(moved_from);
  CHECK_FALSE(moved_from.attached());
  {
    VertexData<int> short_lived(m, 0);  // unregisters when it dies: compact must not touch it
    short_lived[q] = 5;
  }
  m.delete_vertex(p);
  m.compact();
  const VertexId q_now(8);
  CHECK(first[q_now] == 1);
  CHECK(copy[q_now] == 2);
  CHECK(assigned[q_now] == 3);
  CHECK(moved[q_now] == 4);
  CHECK(moved_from.size() == 0);
  // Self-assignment keeps the container attached.
  VertexData<int>& alias = first;
  first = alias;
  CHECK(first.attached());
}

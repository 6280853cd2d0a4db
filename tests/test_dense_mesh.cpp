// dense_mesh: a mesh without tombstones is read as it is, one with tombstones through a compacted copy;
// dense_counts are its counts; original_handle takes a dense index back to the input's own handle.

#include <doctest/doctest.h>

#include <optional>

#include <dlfl/dense_mesh.h>
#include "test_meshes.h"

using namespace dlfl;

TEST_CASE("dense mesh: a mesh without tombstones is itself, one with tombstones a compacted copy") {
  const Mesh cube = test::cube();
  std::optional<Mesh> storage;
  CHECK(&dense_mesh(cube, storage) == &cube);
  CHECK_FALSE(storage.has_value());

  Mesh holey = test::cube();
  holey.create_vertex({5, 5, 5});
  holey.delete_vertex(holey.create_vertex({6, 6, 6}));  // a tombstone at vertex 9
  const Mesh& dense = dense_mesh(holey, storage);
  REQUIRE(storage.has_value());
  CHECK(&dense == &*storage);
  CHECK(dense.vertex_capacity() == dense.num_vertices());
  CHECK(dense.num_vertices() == holey.num_vertices());

  const auto [nv, ne, nf, nc] = dense_counts(dense);
  CHECK(nv == 9);
  CHECK(ne == 12);
  CHECK(nf == 7);  // the point sphere's face
  CHECK(nc == 25);
}

TEST_CASE("dense mesh: original_handle names the input's handle of a dense index") {
  Mesh m = test::cube();
  m.delete_vertex(m.create_vertex({5, 5, 5}));       // vertex 8 and its face 6 removed
  const VertexId kept = m.create_vertex({6, 6, 6});  // vertex 9, dense index 8
  CHECK(original_handle<VertexId>(m, 0) == VertexId(0));
  CHECK(original_handle<VertexId>(m, 8) == kept);
  CHECK(original_handle<FaceId>(m, 6) == m.face(m.corner(kept)));
  CHECK_FALSE(original_handle<VertexId>(m, 9).valid());
}

// set_attribute, the operation added as the registry's example: named attribute values written through
// the editor, undone exactly (the attribute goes away again when the write created it), and logged.

#include <doctest/doctest.h>

#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include "test_meshes.h"

using namespace dlfl;

TEST_CASE("set_attribute: writes create the attribute, undo removes it, redo and replay bring it back") {
  Editor ed;
  ed.set_mesh(build_mesh(test::cube_soup()));
  const Mesh plain = ed.mesh();
  ed.apply("set_attribute", {{"element", "vertex"}, {"name", "weight"}, {"index", 3}, {"value", "0.5"}});
  ed.apply("set_attribute", {{"element", "face"}, {"name", "colour"}, {"index", 2}, {"value", "1,0,0.25"}});
  ed.apply("set_attribute",
           {{"element", "edge"}, {"name", "crease"}, {"index", 7}, {"value", "1"}, {"type", "boolean"}});
  const Mesh& m = ed.mesh();
  CHECK(m.vertex_attribute<double>("weight")[VertexId(3)] == 0.5);
  CHECK(m.vertex_attribute<double>("weight")[VertexId(2)] == 0.0);  // the default
  CHECK(m.face_attribute<glm::dvec3>("colour")[FaceId(2)] == glm::dvec3(1, 0, 0.25));
  CHECK(m.edge_attribute<bool>("crease")[EdgeId(7)]);
  CHECK_FALSE(m.edge_attribute<bool>("crease")[EdgeId(6)]);
  // A second write to an existing attribute keeps its type and records the old value.
  ed.apply("set_attribute", {{"element", "vertex"}, {"name", "weight"}, {"index", 3}, {"value", "2"}});
  CHECK(m.vertex_attribute<double>("weight")[VertexId(3)] == 2.0);
  const Mesh written = ed.mesh();
  CHECK_FALSE(written == plain);  // equality sees attributes
  CHECK(mesh_hash(written) != mesh_hash(plain));
  ed.undo();
  CHECK(m.vertex_attribute<double>("weight")[VertexId(3)] == 0.5);
  for (int i = 0; i < 3; ++i) ed.undo();
  CHECK_FALSE(m.has_vertex_attribute("weight"));
  CHECK_FALSE(m.has_face_attribute("colour"));
  CHECK(m == plain);
  CHECK(mesh_hash(m) == mesh_hash(plain));
  for (int i = 0; i < 4; ++i) ed.redo();
  CHECK(m == written);
  const Editor again = replay_log(log_text(ed));
  CHECK(again.mesh() == written);
  CHECK(mesh_hash(again.mesh()) == mesh_hash(written));
}

TEST_CASE("set_attribute: bad arguments are refused, naming the parameter, before anything changes") {
  Editor ed;
  ed.set_mesh(build_mesh(test::cube_soup()));
  ed.apply("set_attribute", {{"element", "vertex"}, {"name", "w"}, {"index", 0}, {"value", "1"}});
  const Mesh before = ed.mesh();
  auto parameter = [&](const Params& p) {
    try {
      ed.apply("set_attribute", p);
    } catch (const ParameterError& e) {
      return e.parameter();
    }
    FAIL("accepted");
    return std::string();
  };
  CHECK(parameter({{"element", "vertex"}, {"name", "w"}, {"index", 8}, {"value", "1"}}) ==
        "index");  // 8 vertices
  CHECK(parameter({{"element", "vertx"}, {"name", "w"}, {"index", 0}, {"value", "1"}}) == "element");
  CHECK(parameter({{"element", "vertex"}, {"name", "w"}, {"index", 0}, {"value", "1,2,3"}}) == "value");
  CHECK(parameter({{"element", "face"}, {"name", "n"}, {"index", 0}, {"value", "1,2"}}) == "value");
  CHECK(parameter({{"element", "face"}, {"name", "b"}, {"index", 0}, {"value", "2"}, {"type", "boolean"}}) ==
        "value");
  CHECK(
      parameter({{"element", "face"}, {"name", "i"}, {"index", 0}, {"value", "1.5"}, {"type", "integer"}}) ==
      "value");
  CHECK(ed.mesh() == before);
}

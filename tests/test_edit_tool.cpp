// `dlfl ops` and `dlfl edit`: listings that read the registry, operations applied in order, all or nothing,
// usage errors with exit 2, and logs that replay.

#include "tool_runner.h"
#ifdef DLFL_TOOL

#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/operations/operation.h>

using namespace dlfl;
using namespace dlfl::test;

TEST_CASE("tool ops: lists every registered operation, as text and as JSON") {
  const Run text = run("ops");
  REQUIRE(text.exit_code == 0);
  for (const auto& name : operation_names()) {
    CAPTURE(name);
    CHECK(text.out.find(name + "  (") != std::string::npos);
  }
  const Run json = run("ops --json");
  REQUIRE(json.exit_code == 0);
  const auto doc = nlohmann::json::parse(json.out);
  REQUIRE(doc.is_array());
  CHECK(doc.size() == operations().size());
  // insert_edge's two corners, required, typed.
  const Run one = run("ops insert_edge --json");
  REQUIRE(one.exit_code == 0);
  const auto op = nlohmann::json::parse(one.out);
  CHECK(op["name"] == "insert_edge");
  REQUIRE(op["params"].size() == 2);
  CHECK(op["params"][0]["name"] == "corner1");
  CHECK(op["params"][0]["type"] == "corner");
  CHECK(op["params"][0]["optional"] == false);
  // subdivide's iterations has a default and a range.
  const auto sub = nlohmann::json::parse(run("ops subdivide --json").out);
  bool found = false;
  for (const auto& p : sub["params"]) {
    if (p["name"] != "iterations") continue;
    found = true;
    CHECK(p["default"] == 1);  // typed, as in `dlfl schemes --json`
    CHECK(p["range"]["min"] == 0.0);
    CHECK(p["range"]["max"] == 64.0);
  }
  CHECK(found);
  const Run unknown = run("ops insert_edg");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err.find("did you mean 'insert_edge'?") != std::string::npos);
}

TEST_CASE("tool edit: applies operations in order and writes the result and a log that replays") {
  const auto out = scratch("edited.json");
  const auto log = scratch("edited.log.json");
  const auto again = scratch("again.json");
  // On the cube: split face 0 by a diagonal (E+1, F+1), put a vertex on the new edge (V+1, E+1), move it.
  const Run r = run("edit " + example("cube.obj") + " --op 'insert_edge corner1=0 corner2=2'" +
                    " --op 'subdivide_edge edge=12 position=0.1,0.2,-1'" +
                    " --op 'set_position vertex=8 position=0,0,-1.25' -o '" + out.string() + "' --log '" +
                    log.string() + "' --self-contained");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  const Mesh m = read_mesh(out);
  CHECK(m.num_vertices() == 9);
  CHECK(m.num_edges() == 14);
  CHECK(m.num_faces() == 7);
  CHECK(m.position(VertexId(8)) == glm::dvec3(0, 0, -1.25));
  REQUIRE(run("replay '" + log.string() + "' -o '" + again.string() + "'").exit_code == 0);
  CHECK(mesh_hash(read_mesh(again)) == mesh_hash(m));
}

TEST_CASE("tool edit: nothing is written unless every operation succeeds; usage errors exit 2") {
  const auto out = scratch("never.obj");
  const auto log = scratch("never.log.json");
  const std::string tail = " -o '" + out.string() + "' --log '" + log.string() + "'";
  // The second op is a self-loop: the work fails (exit 1).
  const Run loop = run("edit " + example("cube.obj") + " --op 'insert_edge corner1=0 corner2=2'" +
                       " --op 'insert_edge corner1=0 corner2=0'" + tail);
  CHECK(loop.exit_code == 1);
  CHECK(loop.err.rfind("error: --op 2", 0) == 0);
  // Unknown operation, unknown parameter, malformed value, dead handle: usage errors (exit 2).
  for (const char* op : {"insert_edg corner1=0 corner2=2", "insert_edge corner1=0 corner3=2",
                         "set_position vertex=0 position=1,2", "delete_edge edge=999", "insert_edge corner1",
                         "subdivide scheme=honeycomb iterations=100"}) {
    CAPTURE(op);
    const Run bad = run("edit " + example("cube.obj") + " --op '" + op + "'" + tail);
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.rfind("error: ", 0) == 0);
    CHECK(bad.err.find('\n') == bad.err.size() - 1);
  }
  CHECK_FALSE(std::filesystem::exists(out));
  CHECK_FALSE(std::filesystem::exists(log));
}

TEST_CASE("tool edit: schemes and groups run through --op") {
  const auto out = scratch("sub.obj");
  const Run r =
      run("edit " + example("cube.obj") + " --op 'begin_group label=\"two steps\"'" +
          " --op 'subdivide scheme=catmull-clark iterations=2' --op end_group -o '" + out.string() + "'");
  REQUIRE(r.exit_code == 0);
  // Catmull-Clark twice on the cube: F = 6 * 4^2 = 96 quads.
  CHECK(read_mesh(out).num_faces() == 96);
}

#endif

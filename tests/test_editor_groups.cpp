// The editor's groups and history report, any registered operation applied by name, and the logs they
// write: replays give the same mesh and hash, and logs of the previous version still replay.

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/validate.h>
#include "log_helpers.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

// Three edits on the cube: split a face, put a vertex on the new edge, move it.
void three_edits(Editor& ed) {
  const CornerId c = ed.mesh().first_corner(FaceId(0));
  const InsertEdgeResult r = ed.insert_edge(c, ed.mesh().next(ed.mesh().next(c)));
  const VertexId v = ed.subdivide_edge(r.edge, glm::dvec3(0.5, 0.25, -1));
  ed.set_position(v, glm::dvec3(0.5, 0.25, -1.5));
}

}  // namespace

TEST_CASE("editor: a group is one undo entry, labelled, and undoes to where it began") {
  Editor ed;
  ed.set_mesh(build_mesh(test::cube_soup()));
  const Mesh start = ed.mesh();
  ed.begin_group("bevel");
  three_edits(ed);
  ed.end_group();
  const Mesh end = ed.mesh();
  // Independently: V+1, E+2, F+1 from one split (E+1, F+1) and one edge subdivision (V+1, E+1).
  CHECK(end.num_vertices() == 9);
  CHECK(end.num_edges() == 14);
  CHECK(end.num_faces() == 7);
  const auto history = ed.undo_history();
  REQUIRE(history.size() == 2);  // the mesh, then the group
  CHECK(history[0].label == "mesh");
  CHECK(history[1].label == "bevel");
  CHECK(history[1].operations == 3);
  REQUIRE(ed.undo());
  CHECK(ed.mesh() == start);
  CHECK(ed.redo_history().size() == 1);
  REQUIRE(ed.redo());
  CHECK(ed.mesh() == end);
  CHECK(mesh_hash(ed.mesh()) == mesh_hash(end));
}

TEST_CASE("editor: groups nest into the outermost, empty groups add nothing, misuse is refused") {
  Editor ed;
  ed.set_mesh(build_mesh(test::cube_soup()));
  const Mesh start = ed.mesh();
  ed.begin_group("outer");
  ed.begin_group("inner");
  three_edits(ed);
  CHECK(ed.group_depth() == 2);
  CHECK_THROWS_AS(ed.undo(), InvalidArgument);
  CHECK_THROWS_AS(ed.redo(), InvalidArgument);
  CHECK_THROWS_AS(ed.clear_history(), InvalidArgument);
  ed.end_group();
  ed.subdivide("catmull-clark");  // a whole-mesh step inside the same group
  ed.end_group();
  CHECK(ed.group_depth() == 0);
  REQUIRE(ed.undo_history().size() == 2);
  CHECK(ed.undo_history()[1].label == "outer");
  CHECK(ed.undo_history()[1].operations == 4);
  REQUIRE(ed.undo());
  CHECK(ed.mesh() == start);
  ed.begin_group("nothing");
  ed.end_group();
  CHECK(ed.undo_history().size() == 1);
  CHECK_THROWS_AS(ed.end_group(), InvalidArgument);
  ed.clear_history();
  CHECK_FALSE(ed.can_undo());
  CHECK_FALSE(ed.can_redo());
  CHECK(ed.mesh() == start);  // clearing the history keeps the mesh
}

TEST_CASE("editor: a failing operation inside a group changes nothing and the group goes on") {
  Editor ed;
  ed.set_mesh(build_mesh(test::cube_soup()));
  ed.begin_group("g");
  three_edits(ed);
  const Mesh middle = ed.mesh();
  const std::size_t logged = ed.log().size();
  const CornerId c = ed.mesh().first_corner(FaceId(1));
  CHECK_THROWS_AS(ed.insert_edge(c, c), TopologyError);
  CHECK_THROWS_AS(ed.apply("subdivide", {{"scheme", "honeycomb"}, {"params", Params{{"t", 3}}}}),
                  ParameterError);
  CHECK(ed.mesh() == middle);
  CHECK(ed.log().size() == logged);
  ed.end_group();
  REQUIRE(ed.undo_history().size() == 2);
  CHECK(ed.undo_history()[1].operations == 3);
}

TEST_CASE("editor: the undo limit counts groups as one entry each") {
  Editor ed(Editor::Options{false, 2});
  ed.set_mesh(build_mesh(test::cube_soup()));
  for (int i = 0; i < 3; ++i) {
    ed.begin_group(std::string("g") + std::to_string(i));
    three_edits(ed);
    ed.end_group();
  }
  const auto history = ed.undo_history();
  REQUIRE(history.size() == 2);
  CHECK(history[0].label == "g1");
  CHECK(history[1].label == "g2");
}

TEST_CASE("editor: a session with groups, undo and redo replays from its log to the same hash") {
  Editor ed(Editor::Options{true, 0});
  ed.set_mesh(build_mesh(test::torus_soup(4, 4)), "torus.obj");
  ed.begin_group("edits");
  three_edits(ed);
  ed.end_group();
  ed.apply("subdivide", {{"scheme", "honeycomb"}, {"params", Params{{"t", 1}}}});
  ed.undo();
  ed.redo();
  ed.begin_group("more");
  ed.create_vertex(glm::dvec3(1, 2, 3));
  ed.end_group();
  ed.undo();
  const std::string text = log_text(ed);
  const Editor again = replay_log(text);
  CHECK(again.mesh() == ed.mesh());
  CHECK(mesh_hash(again.mesh()) == mesh_hash(ed.mesh()));
  CHECK(again.undo_history().size() == ed.undo_history().size());
  CHECK(again.redo_history().size() == ed.redo_history().size());
  // The log names the groups.
  const auto log = test::log_json(ed);
  int begins = 0;
  for (const auto& op : log["ops"]) begins += op["op"] == "begin_group" ? 1 : 0;
  CHECK(begins == 2);
  CHECK(log["version"] == oplog_version);
}

TEST_CASE("oplog: logs written before the operation registry replay to the hash they had then") {
  // Written by the previous code (tests/data/oplog_v1/make_fixtures.cpp.txt), with the hash of the mesh
  // each session ended with, computed by that code.
  const std::filesystem::path dir = std::filesystem::path(DLFL_SOURCE_DIR) / "tests/data/oplog_v1";
  for (const char* name : {"v1_euler_honeycomb", "v1_zhang_wang", "v1_meng_prautzsch", "v1_triangles"}) {
    CAPTURE(name);
    const Editor ed = replay_log_file(dir / (std::string(name) + ".json"));
    std::string expected = test::read_text(dir / (std::string(name) + ".hash"));
    while (!expected.empty() && expected.back() == '\n') expected.pop_back();
    CHECK(mesh_hash(ed.mesh()) == expected);
    CHECK(validate(ed.mesh()).valid());
    // Written again by this code, the session replays to the same hash.
    CHECK(mesh_hash(replay_log(log_text(ed)).mesh()) == expected);
  }
}

TEST_CASE("oplog: logs written before the boundary rules replay with the hole rule, to the hash they had") {
  // tests/data/oplog_v2/README.md: subdivisions of open meshes, written by the code before `boundary`.
  const std::filesystem::path dir = std::filesystem::path(DLFL_SOURCE_DIR) / "tests/data/oplog_v2";
  for (const char* name : {"v2_open_tube_catmull-clark", "v2_open_tube_doo-sabin", "v2_open_tube_honeycomb",
                           "v2_open_tube_honeycomb-zw", "v2_open_tetra_loop"}) {
    CAPTURE(name);
    const Editor ed = replay_log_file(dir / (std::string(name) + ".json"));
    std::string expected = test::read_text(dir / (std::string(name) + ".hash"));
    while (!expected.empty() && expected.back() == '\n') expected.pop_back();
    CHECK(mesh_hash(ed.mesh()) == expected);
    // Written again by this code (version 3), the session records the rule it ran with and replays the same.
    const std::string again = log_text(ed);
    CHECK(nlohmann::json::parse(again)["version"] == 3);
    CHECK(mesh_hash(replay_log(again).mesh()) == expected);
  }
}

TEST_CASE("oplog: a log written by hand may leave out parameters that have defaults") {
  nlohmann::json log = {{"format", "dlfl-oplog"},
                        {"version", oplog_version},
                        {"ops",
                         {{{"op", "create_face_manifold"}, {"positions", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}},
                          {{"op", "subdivide"}, {"scheme", "honeycomb"}},
                          {{"op", "subdivide_edge"}, {"edge", 0}}}}};
  const Editor ed = test::replay_json(log);
  // A triangle manifold (V 3, E 3, F 2), one honeycomb step (V' = 2E = 6, E' = 3E = 9, F' = F + V = 5), then
  // one edge subdivision (V+1, E+1).
  CHECK(ed.mesh().num_vertices() == 7);
  CHECK(ed.mesh().num_edges() == 10);
  CHECK(ed.mesh().num_faces() == 5);
  // The replayed editor logs every parameter in force.
  const auto full = test::log_json(ed);
  CHECK(full["ops"][1]["iterations"] == 1);
  CHECK(full["ops"][1]["params"]["t"] == 0.5);
}

TEST_CASE("oplog: every parameter error names the op index and the field, before anything runs") {
  auto error = [](nlohmann::json ops) {
    const nlohmann::json log = {
        {"format", "dlfl-oplog"}, {"version", oplog_version}, {"ops", std::move(ops)}};
    try {
      test::replay_json(log, "hand.json");
    } catch (const LogError& e) {
      return std::pair<std::size_t, std::string>{e.op(), e.field()};
    }
    FAIL("replayed");
    return std::pair<std::size_t, std::string>{};
  };
  const nlohmann::json square = {{"op", "create_face_manifold"},
                                 {"positions", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}};
  using P = std::pair<std::size_t, std::string>;
  CHECK(error({square, {{"op", "insert_edge"}, {"corner1", 0}, {"corner3", 1}}}) == P{1, "corner3"});
  CHECK(error({square, {{"op", "insert_edge"}, {"corner1", 0}}}) == P{1, "corner2"});
  CHECK(error({square, {{"op", "insert_edge"}, {"corner1", "zero"}, {"corner2", 1}}}) == P{1, "corner1"});
  CHECK(error({square, {{"op", "delete_edge"}, {"edge", 99}}}) == P{1, "edge"});
  CHECK(error({square, {{"op", "set_position"}, {"vertex", 0}, {"position", {1, 2}}}}) == P{1, "position"});
  CHECK(error({square, {{"op", "subdivide"}, {"scheme", "honeycomb"}, {"iterations", 65}}}) ==
        P{1, "iterations"});
  CHECK(error({square, {{"op", "subdivide"}, {"scheme", "honeycom"}}}) == P{1, "scheme"});
  CHECK(error({square, {{"op", "frobnicate"}}}) == P{1, "op"});
  CHECK(error({{{"op", "undo"}}}) == P{0, "op"});
  CHECK(error({{{"op", "end_group"}}}) == P{0, "op"});
}

TEST_CASE("editor without history: the same meshes and log, nothing to undo, groups counted") {
  Editor::Options no_history;
  no_history.keep_history = false;
  Editor kept, dropped(no_history);
  for (Editor* ed : {&kept, &dropped}) {
    ed->set_mesh(build_mesh(test::cube_soup()));
    ed->subdivide("catmull-clark");
    ed->begin_group("edits");
    three_edits(*ed);
    ed->end_group();
  }
  CHECK(dropped.mesh() == kept.mesh());
  CHECK(log_text(dropped) == log_text(kept));
  CHECK(kept.undo_history().size() == 3);  // the load, the subdivision, the group
  CHECK(dropped.undo_history().empty());
  CHECK_FALSE(dropped.undo());
  CHECK_THROWS_AS(dropped.apply("undo"), InvalidArgument);
  CHECK(dropped.mesh() == kept.mesh());  // the refused undo changed nothing
}

TEST_CASE("replay without history: the same mesh; a log that undoes keeps its history anyway") {
  Editor ed;
  ed.set_mesh(build_mesh(test::cube_soup()));
  ed.subdivide("catmull-clark");
  ed.subdivide("doo-sabin");
  ed.undo();  // back to the Catmull-Clark mesh: the replay needs the history for this op
  const std::string undoing = log_text(ed);
  ReplayOptions options;
  options.keep_history = false;
  const Editor replayed = replay_log(undoing, "undoing", options);
  CHECK(replayed.mesh() == ed.mesh());
  CHECK(replayed.undo_history().size() == 2);  // kept: the load and the subdivision left after the undo

  Editor plain;
  plain.set_mesh(build_mesh(test::cube_soup()));
  plain.subdivide("catmull-clark", {}, 2);
  const Editor lean = replay_log(log_text(plain), "plain", options);
  CHECK(lean.mesh() == plain.mesh());
  CHECK(lean.undo_history().empty());
}

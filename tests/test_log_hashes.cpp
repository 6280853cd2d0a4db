// Logs carry the hash of each loaded mesh and of the final mesh; replay checks them unless told not to.

#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include "test_helpers.h"
#include "tool_runner.h"

namespace fs = std::filesystem;
using namespace dlfl;
using namespace dlfl::test;

namespace {

const std::string tetrahedron_obj =
    "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
// The same tetrahedron with its first vertex moved: same topology, another mesh.
const std::string moved_obj =
    "v 2 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";

// A log of the file `in`, loaded and subdivided once.
std::string session_log(const fs::path& in, bool self_contained) {
  Editor::Options options;
  options.embed_meshes = self_contained;
  Editor editor(options);
  editor.set_mesh(read_mesh(in), in);
  editor.subdivide("honeycomb");
  return log_text(editor);
}

void expect_log_error(const std::string& log, std::size_t op, const std::string& field) {
  try {
    (void)replay_log(log);
    FAIL("the replay was expected to fail");
  } catch (const LogError& e) {
    CHECK(e.op() == op);
    CHECK(e.field() == field);
  }
}

}  // namespace

TEST_CASE("log hashes: the load op and the document carry the hashes of the input and the final mesh") {
  ScratchDir dir;
  write_text(dir / "t.obj", tetrahedron_obj);
  const nlohmann::json doc = nlohmann::json::parse(session_log(dir / "t.obj", false));
  CHECK(doc["ops"][0]["op"] == "load");
  CHECK(doc["ops"][0]["hash"] == mesh_hash(read_mesh(dir / "t.obj")));
  const Editor replayed = replay_log(doc.dump());
  CHECK(doc["final_hash"] == mesh_hash(replayed.mesh()));
}

TEST_CASE(
    "log hashes: an input changed since the log was written fails at its load op, unless not verified") {
  ScratchDir dir;
  write_text(dir / "t.obj", tetrahedron_obj);
  const std::string log = session_log(dir / "t.obj", false);
  CHECK_NOTHROW(replay_log(log));
  write_text(dir / "t.obj", moved_obj);
  expect_log_error(log, 0, "hash");
  ReplayOptions unverified;
  unverified.verify = false;
  const Editor now = replay_log(log, "log", unverified);
  Editor expected;
  expected.set_mesh(read_mesh(dir / "t.obj"));
  expected.subdivide("honeycomb");
  CHECK(now.mesh() == expected.mesh());

  // A self-contained log does not depend on the file: it replays whatever the file holds now.
  write_text(dir / "t.obj", tetrahedron_obj);
  const std::string embedded = session_log(dir / "t.obj", true);
  write_text(dir / "t.obj", moved_obj);
  CHECK_NOTHROW(replay_log(embedded));

  // A missing input is the fault of the path.
  fs::remove(dir / "t.obj");
  expect_log_error(log, 0, "path");
}

TEST_CASE("log hashes: an edited final hash is refused, and a log without hashes replays as before") {
  ScratchDir dir;
  write_text(dir / "t.obj", tetrahedron_obj);
  nlohmann::json doc = nlohmann::json::parse(session_log(dir / "t.obj", false));
  doc["final_hash"] = std::string(32, '0');
  expect_log_error(doc.dump(), LogError::npos, "final_hash");
  ReplayOptions unverified;
  unverified.verify = false;
  CHECK_NOTHROW(replay_log(doc.dump(), "log", unverified));
  doc["final_hash"] = 7;
  expect_log_error(doc.dump(), LogError::npos, "final_hash");

  doc.erase("final_hash");
  doc["ops"][0].erase("hash");
  CHECK(replay_log(doc.dump()).mesh().num_vertices() > 4);
}

#ifdef DLFL_TOOL
TEST_CASE("tool: replay fails naming the op when a non-self-contained input changed; --no-verify replays") {
  ScratchDir dir;
  write_text(dir / "t.obj", tetrahedron_obj);
  const std::string q = "'" + dir.path().string() + "/";
  REQUIRE(run("subdivide " + q + "t.obj' -s honeycomb -o " + q + "a.obj' --log " + q + "l.json'").exit_code ==
          0);
  CHECK(run("replay " + q + "l.json' -o " + q + "b.obj'").exit_code == 0);
  write_text(dir / "t.obj", moved_obj);
  Run r = run("replay " + q + "l.json' -o " + q + "c.obj'");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("op 0") != std::string::npos);
  CHECK(r.err.find("has changed") != std::string::npos);
  CHECK(!fs::exists(dir / "c.obj"));
  CHECK(run("replay " + q + "l.json' -o " + q + "c.obj' --no-verify").exit_code == 0);
  CHECK(fs::exists(dir / "c.obj"));
}
#endif

TEST_CASE("log replay: after_op sees each op's mesh in order, the last one the replay's result") {
  const auto in = scratch_file("after_op.obj", tetrahedron_obj);
  Editor::Options options;
  options.embed_meshes = true;
  Editor editor(options);
  editor.set_mesh(read_mesh(in), in);
  editor.subdivide("honeycomb");
  editor.undo();
  const Mesh tetrahedron = read_mesh(in);
  std::vector<std::string> seen;
  std::vector<std::size_t> faces;
  ReplayOptions replay;
  replay.after_op = [&](const Editor& at, std::size_t op) {
    CHECK(op == seen.size());
    seen.push_back(at.log().back().name);
    faces.push_back(at.mesh().num_faces());
  };
  const Editor replayed = replay_log(log_text(editor), "log", replay);
  CHECK(seen == std::vector<std::string>{"load", "subdivide", "undo"});
  // Honeycomb on a tetrahedron: a hexagon per triangle and a triangle per vertex, 4 + 4 faces; undo gives 4.
  CHECK(faces == std::vector<std::size_t>{4, 8, 4});
  CHECK(replayed.mesh() == tetrahedron);
}

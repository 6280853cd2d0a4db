// The dlfl tool's contract: JSON keys and values, exit codes, one-line errors, no partial outputs.

#include <doctest/doctest.h>

#ifdef DLFL_TOOL
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/schemes/scheme_registry.h>
#include "tool_runner.h"

using namespace dlfl::test;

TEST_CASE("tool: info on the cube reports the hand-counted figures") {
  Run r = run("info " + example("cube.obj"));
  REQUIRE(r.exit_code == 0);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j["vertices"] == 8);
  CHECK(j["edges"] == 12);
  CHECK(j["faces"] == 6);
  CHECK(j["corners"] == 24);
  CHECK(j["holes"] == 0);
  CHECK(j["components"] == 1);
  CHECK(j["euler_characteristic"] == 2);
  CHECK(j["genus"] == nlohmann::json::array({0}));
  CHECK(j["valid"] == true);
  CHECK(j["face_sizes"] == nlohmann::json({{"4", 6}}));
  CHECK(j["valences"] == nlohmann::json({{"3", 8}}));
  CHECK(j["bbox"] == nlohmann::json({{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}));
  CHECK(j["hash"].get<std::string>().size() == 32);
}

TEST_CASE("tool: the hash is equal for equal meshes and differs for different ones") {
  const auto ply = scratch("cube.ply");
  REQUIRE(run("convert " + example("cube.obj") + " '" + ply.string() + "'").exit_code == 0);
  auto a = nlohmann::json::parse(run("info " + example("cube.obj")).out);
  auto b = nlohmann::json::parse(run("info '" + ply.string() + "'").out);
  auto c = nlohmann::json::parse(run("info " + example("dodecahedron.obj")).out);
  CHECK(a["hash"] == b["hash"]);
  CHECK(a["hash"] != c["hash"]);
}

TEST_CASE("tool: check exits 0 on a valid mesh") {
  Run r = run("check " + example("tetrahedron.off"));
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
}

TEST_CASE("tool: bad input gives one error line and exit 1 while usage errors exit 2 and --help exits 0") {
  Run missing = run("info /nonexistent/mesh.obj");
  CHECK(missing.exit_code == 1);
  CHECK(missing.err.rfind("error: ", 0) == 0);
  CHECK(std::count(missing.err.begin(), missing.err.end(), '\n') == 1);

  const auto bad = scratch("bad.obj");
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
  Run out_of_range = run("check '" + bad.string() + "'");
  CHECK(out_of_range.exit_code == 1);
  CHECK(out_of_range.err.find(":4:") != std::string::npos);  // the face's line

  CHECK(run("").exit_code == 2);
  CHECK(run("info").exit_code == 2);
  CHECK(run("frobnicate x").exit_code == 2);
  CHECK(run("info --no-such-flag " + example("cube.obj")).exit_code == 2);
  for (const char* help : {"--help", "info --help", "check --help", "convert --help"}) {
    Run h = run(help);
    CHECK(h.exit_code == 0);
    CHECK(h.out.find("Usage") != std::string::npos);
  }
}

TEST_CASE("tool: a failed convert leaves no output file") {
  const auto out = scratch("never.obj");
  Run r = run("convert /nonexistent/in.obj '" + out.string() + "'");
  CHECK(r.exit_code == 1);
  CHECK_FALSE(std::filesystem::exists(out));
  Run wrong_ext = run("convert " + example("cube.obj") + " '" + scratch("cube.xyz").string() + "'");
  CHECK(wrong_ext.exit_code == 1);
  CHECK_FALSE(std::filesystem::exists(scratch("cube.xyz")));
}
TEST_CASE("tool: every kind of bad input file gets one located error line and leaves the output alone") {
  // Each case: file name, content, and the "file:line:" prefix the error must carry (line 0: none).
  const std::string tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  struct Case {
    std::string name;
    std::string content;
    int line;
  };
  const Case cases[] = {
      {"range.obj", tetra + "f 1 2 5\n", 5},                              // index out of range
      {"repeat.obj", tetra + "f 1 2 2\n", 5},                             // a vertex twice in a row
      {"direction.obj", tetra + "f 1 2 3\nf 1 2 4\n", 6},                 // an edge twice in one direction
      {"bowtie.obj", tetra + "v 1 1 0\nv 2 0 0\nf 1 2 3\nf 1 5 6\n", 1},  // non-manifold vertex 1
      {"nan.obj", "v 0 0 0\nv nan 0 0\n", 2},                             // not finite
      {"short.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n", 4},  // truncated: located at its last line
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    const auto in = scratch(c.name.c_str());
    std::ofstream(in) << c.content;
    const auto out = scratch("out.ply");
    Run r = run("convert '" + in.string() + "' '" + out.string() + "'");
    CHECK(r.exit_code == 1);
    CHECK(r.err.rfind("error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find(in.string() + ":" + std::to_string(c.line) + ":") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
    // An existing output file is not touched either.
    std::ofstream(out) << "keep";
    CHECK(run("convert '" + in.string() + "' '" + out.string() + "'").exit_code == 1);
    CHECK(read_text(out) == "keep");
  }
}

TEST_CASE("tool: subdivide writes the honeycomb and a log that replays to the same mesh") {
  const auto out = scratch("dodeca2.json");
  const auto log = scratch("dodeca2.log.json");
  Run r = run("subdivide " + example("dodecahedron.obj") + " -s honeycomb -n 2 --param t=0.5 -o '" +
              out.string() + "' --log '" + log.string() + "' --self-contained");
  REQUIRE(r.exit_code == 0);
  // Dodecahedron V=20 E=30 F=12: one step gives V=60 E=90 F=32, two give V=180 E=270 F=92.
  auto j = nlohmann::json::parse(run("info '" + out.string() + "'").out);
  CHECK(j["vertices"] == 180);
  CHECK(j["edges"] == 270);
  CHECK(j["faces"] == 92);
  CHECK(j["valences"] == nlohmann::json({{"3", 180}}));
  const auto replayed = scratch("replayed.json");
  REQUIRE(run("replay '" + log.string() + "' -o '" + replayed.string() + "'").exit_code == 0);
  auto k = nlohmann::json::parse(run("info '" + replayed.string() + "'").out);
  CHECK(k["hash"] == j["hash"]);
  // The log records every parameter, defaults included.
  std::ifstream in(log);
  auto doc = nlohmann::json::parse(in);
  CHECK(doc["ops"][1]["params"] == nlohmann::json({{"t", 0.5},
                                                   {"a0", 0.45},
                                                   {"a1", 1.25},
                                                   {"boundary", "curve"},
                                                   {"sharp_corners", true},
                                                   {"planarize", 0}}));
}

TEST_CASE(
    "tool: subdivide rejects bad parameters with one line, exit 2 (a usage error), and writes nothing") {
  const auto out = scratch("never2.obj");
  for (const char* params :
       {"--param t=1.5", "--param a=0", "--param nope=1", "--param t", "--param a=0.5 --param a0=0.4"}) {
    CAPTURE(params);
    Run r =
        run("subdivide " + example("cube.obj") + " -s honeycomb " + params + " -o '" + out.string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(out));
  }
  CHECK(run("subdivide " + example("cube.obj") + " -s nosuch -o '" + out.string() + "'").exit_code == 2);
  CHECK(run("subdivide " + example("cube.obj") + " -o '" + out.string() + "'").exit_code == 2);  // no -s
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("tool: replay of a malformed log names the op and writes nothing") {
  const auto log = scratch("bad.log.json");
  std::ofstream(log)
      << R"({"format": "dlfl-oplog", "version": 1, "ops": [{"op": "create_vertex", "position": [0, 0, 0]},
    {"op": "delete_edge", "edge": 4}]})";
  const auto out = scratch("never3.json");
  Run r = run("replay '" + log.string() + "' -o '" + out.string() + "'");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("op 1") != std::string::npos);
  CHECK(r.err.find("'edge'") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}
TEST_CASE("tool: convert of a malformed input names the line and writes nothing") {
  const auto bad = scratch("fin.obj");
  // Three triangles on the edge 1-2: an edge of more than two faces.
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 2 1 5\n";
  const auto out = scratch("fin.ply");
  std::ofstream(out) << "old content";
  Run r = run("convert '" + bad.string() + "' '" + out.string() + "'");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find(":8:") != std::string::npos);
  CHECK(read_text(out) == "old content");  // the existing file is untouched
}

TEST_CASE("tool: every registered scheme subdivides the tetrahedron into a valid mesh") {
  // The tetrahedron is a triangle mesh (Loop, sqrt3), closed (dual), convex with its centroid inside
  // (Meng-Prautzsch): every scheme must accept it. One step never loses faces or vertices.
  for (const std::string& scheme : dlfl::scheme_names()) {
    CAPTURE(scheme);
    const auto out = scratch("scheme.json");
    Run r = run("subdivide " + example("tetrahedron.off") + " -s " + scheme + " -o '" + out.string() + "'");
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    Run check = run("check '" + out.string() + "'");
    CHECK(check.exit_code == 0);
    Run info = run("info '" + out.string() + "'");
    REQUIRE(info.exit_code == 0);
    const auto doc = nlohmann::json::parse(info.out);
    CHECK(doc["valid"] == true);
    CHECK(doc["genus"] == nlohmann::json::array({0}));
    CHECK(doc["faces"].get<int>() >= 4);
    CHECK(doc["vertices"].get<int>() >= 4);
  }
}
#endif

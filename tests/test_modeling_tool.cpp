// The modeling operations from the tool: listed by `dlfl ops`, run by `dlfl edit --op`, and the bundled
// genus-3 session log replayed by `dlfl replay`.

#include <doctest/doctest.h>

#ifdef DLFL_TOOL
#include <nlohmann/json.hpp>
#include <string>

#include "tool_runner.h"

using namespace dlfl::test;

TEST_CASE("tool: dlfl ops lists every modeling operation with its contract fields") {
  const Run r = run("ops --json");
  REQUIRE(r.exit_code == 0);
  const auto listing = nlohmann::json::parse(r.out);
  // The names and fields of the modeling issue's contract.
  const std::pair<const char*, std::vector<const char*>> contract[] = {
      {"collapse_edge", {"edge", "position", "cleanup"}},
      {"splice_corners", {"corner1", "corner2"}},
      {"divide_edge", {"edge", "segments"}},
      {"flip_edge", {"edge"}},
      {"stellate_face", {"face", "faces", "height"}},
      {"subdivide_face", {"face", "style"}},
      {"triangulate", {"faces"}},
      {"reverse_orientation", {}},
      {"make_hole", {"face"}},
      {"fill_hole", {"face"}},
      {"transform", {"translate", "scale", "rotate_axis", "rotate_degrees", "center"}},
      {"connect_edges", {"corner1", "corner2"}},
      {"connect_faces",
       {"face1", "face2", "corner1", "corner2", "segments", "curve", "weight1", "weight2", "twist", "pinch",
        "bubble"}},
      {"extrude_face",
       {"face", "faces", "distance", "segments", "rotate_degrees", "scale", "direction", "style"}},
      {"inset_face", {"face", "faces", "amount", "depth"}},
  };
  for (const auto& [name, fields] : contract) {
    const auto& name_ = name;  // clang 14 cannot capture a structured binding
    CAPTURE(name_);
    const nlohmann::json* op = nullptr;
    for (const auto& o : listing) {
      if (o["name"] == name) op = &o;
    }
    REQUIRE(op != nullptr);
    for (const char* field : fields) {
      CAPTURE(field);
      bool found = false;
      for (const auto& p : (*op)["params"]) found = found || p["name"] == field;
      CHECK(found);
    }
  }
}

TEST_CASE("tool: dlfl edit extrudes a face of the cube (V+4, E+8, F+4)") {
  const auto out = scratch("cube-extruded.obj");
  REQUIRE(
      run("edit " + example("cube.obj") + " --op 'extrude_face face=0 distance=2' -o '" + out.string() + "'")
          .exit_code == 0);
  const auto info = nlohmann::json::parse(run("info '" + out.string() + "'").out);
  CHECK(info["vertices"] == 12);
  CHECK(info["edges"] == 20);
  CHECK(info["faces"] == 10);
  CHECK(info["genus"] == nlohmann::json::array({0}));
  // A refused argument: a usage error naming the parameter, and no output.
  const auto refused = scratch("refused.obj");
  const Run r = run("edit " + example("cube.obj") + " --op 'extrude_face face=0 segments=0' -o '" +
                    refused.string() + "'");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("segments") != std::string::npos);
  CHECK(!std::filesystem::exists(refused));
}

TEST_CASE("tool: the bundled modelling sessions replay to meshes of the hand-counted size and genus") {
  struct Session {
    const char* log;
    long vertices, edges, faces, genus;
  };
  const Session sessions[] = {
      // Cube 8/12/6; extrude_face (cubical, a quad): V+4, E+8, F+4 -> 12/20/10; three connect_faces between
      // quads with 8 segments: each V+4*7, E+4*8+4*7, F-2+4*8 -> 96/200/100; two Catmull-Clark steps of an
      // all-quad mesh (V+E+F, 2E+4F, 4F) -> 396/800/400 -> 1596/3200/1600. Euler characteristic -4: genus 3.
      {"genus3_handles.log.json", 1596, 3200, 1600, 3},
      // Cube, two Catmull-Clark steps -> 26/48/24 -> 98/192/96; rind with k = 6 quads: V+V, E+E+4k,
      // F+F+2k -> 196/408/204 (Euler characteristic 2*2 - 2*6 = -8); Catmull-Clark -> 808/1632/816: genus 5.
      {"rind_lantern.log.json", 808, 1632, 816, 5},
      // Dodecahedron 20/30/12; wireframe: 2V+4E, 12E, 6E -> 160/360/180 (genus E - V + 1 = 11);
      // Catmull-Clark of those quads -> 700/1440/720.
      {"wireframe_dodecahedron.log.json", 700, 1440, 720, 11},
  };
  for (const Session& session : sessions) {
    CAPTURE(session.log);
    const auto out = scratch(std::string(session.log) + ".obj");
    const Run r = run("replay " + example(session.log) + " -o '" + out.string() + "'");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const auto info = nlohmann::json::parse(run("info '" + out.string() + "'").out);
    CHECK(info["vertices"] == session.vertices);
    CHECK(info["edges"] == session.edges);
    CHECK(info["faces"] == session.faces);
    CHECK(info["genus"] == nlohmann::json::array({session.genus}));
    CHECK(info["valid"] == true);
  }
}
#endif

// The dlfl tool with the Meng-Prautzsch schemes: info --angles, subdivide with mp-honeycomb, mp-pushing and
// mhp, logs that replay, and one-line errors that leave no output behind.

#include <doctest/doctest.h>

#ifdef DLFL_TOOL
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tool_runner.h"

using namespace dlfl::test;

namespace {

// Exit 2 for a bad parameter (a usage error), 1 for an input the scheme refuses.
void check_one_line_error(const Run& r, const std::string& needle, int exit_code = 1) {
  CAPTURE(r.err);
  CHECK(r.exit_code == exit_code);
  CHECK(r.err.rfind("error: ", 0) == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find(needle) != std::string::npos);
}

// The octahedron with its top vertex pushed below the equator: planar triangles, concave along the equator.
std::filesystem::path dented_octahedron_obj() {
  return scratch_file("dented.obj",
                      "v 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nv 0 0 -0.5\nv 0 0 -1\n"
                      "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n"
                      "f 2 1 6\nf 3 2 6\nf 4 3 6\nf 1 4 6\n");
}

}  // namespace

TEST_CASE("mp tool: info --angles adds the hand-computed cube angles and keeps every other key") {
  Run plain = run("info " + example("cube.obj"));
  Run with = run("info --angles " + example("cube.obj"));
  REQUIRE(plain.exit_code == 0);
  REQUIRE(with.exit_code == 0);
  auto a = nlohmann::json::parse(plain.out);
  auto b = nlohmann::json::parse(with.out);
  const auto angles = b["angles"];
  b.erase("angles");
  CHECK(a == b);
  // Adjacent cube normals are perpendicular; a face shares vertices with both faces of an opposite pair.
  CHECK(angles["unit"] == "degree");
  CHECK(angles["edge"]["max"].get<double>() == doctest::Approx(90.0));
  CHECK(angles["edge"]["mean"].get<double>() == doctest::Approx(90.0));
  CHECK(angles["vertex"]["max"].get<double>() == doctest::Approx(90.0));
  CHECK(angles["vertex"]["mean"].get<double>() == doctest::Approx(90.0));
  CHECK(angles["face"]["max"].get<double>() == doctest::Approx(180.0));
  CHECK(angles["face"]["mean"].get<double>() == doctest::Approx(180.0));
  CHECK(angles["convex"] == true);
  CHECK_FALSE(angles.contains("not_convex_because"));

  Run dented = run("info --angles '" + dented_octahedron_obj().string() + "'");
  REQUIRE(dented.exit_code == 0);
  const auto d = nlohmann::json::parse(dented.out)["angles"];
  CHECK(d["convex"] == false);
  CHECK(d["not_convex_because"].get<std::string>().find("concave") != std::string::npos);
}

TEST_CASE("mp tool: subdivide with each scheme gives the closed-form counts") {
  // Cube: H gives V + 2E = 32, 4E = 48, F + E = 18 (6 quads, 12 hexagons, all vertices 3-valent);
  // P gives V + E = 20, 48, F + 2E = 30 (6 quads, 24 triangles; 8 vertices of valence 3, 12 of valence 6).
  struct Case {
    std::string args;
    int v, e, f;
    nlohmann::json face_sizes, valences;
  };
  const Case cases[] = {
      {"-s mp-honeycomb", 32, 48, 18, {{"4", 6}, {"6", 12}}, {{"3", 32}}},
      {"-s mp-pushing --param tau=0.3 --param center=0.1,0,0",
       20,
       48,
       30,
       {{"3", 24}, {"4", 6}},
       {{"3", 8}, {"6", 12}}},
      // HP: H as above, then P on 32 / 48 / 18: V + E = 80, 4E = 192, F + 2E = 114.
      {"-s mhp", 80, 192, 114, {{"3", 96}, {"4", 6}, {"6", 12}}, {{"3", 32}, {"6", 48}}},
      {"-s mp-honeycomb --param random=1 --param seed=3 --param epsilon=0.1",
       32,
       48,
       18,
       {{"4", 6}, {"6", 12}},
       {{"3", 32}}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const auto out = scratch("mp.obj");
    Run r = run("subdivide " + example("cube.obj") + " " + c.args + " -o '" + out.string() + "'");
    REQUIRE(r.exit_code == 0);
    Run info = run("info --angles '" + out.string() + "'");
    REQUIRE(info.exit_code == 0);
    const auto j = nlohmann::json::parse(info.out);
    CHECK(j["vertices"] == c.v);
    CHECK(j["edges"] == c.e);
    CHECK(j["faces"] == c.f);
    CHECK(j["face_sizes"] == c.face_sizes);
    CHECK(j["valences"] == c.valences);
    CHECK(j["valid"] == true);
    CHECK(j["angles"]["convex"] == true);
  }
}

TEST_CASE("mp tool: an mhp log records the pattern and replays to the same mesh") {
  const auto out = scratch("mhp.json");
  const auto log = scratch("mhp.log.json");
  Run r = run("subdivide " + example("tetrahedron.off") +
              " -s mhp --param 'pattern=(PH)2' --param tau_h=0.3 -o '" + out.string() + "' --log '" +
              log.string() + "' --self-contained");
  REQUIRE(r.exit_code == 0);
  const std::string text = read_text(log);
  CHECK(text.find("(PH)2") != std::string::npos);
  CHECK(text.find("tau_p") != std::string::npos);  // defaults are recorded too
  const auto replayed = scratch("replayed.json");
  REQUIRE(run("replay '" + log.string() + "' -o '" + replayed.string() + "'").exit_code == 0);
  auto a = nlohmann::json::parse(run("info '" + out.string() + "'").out);
  auto b = nlohmann::json::parse(run("info '" + replayed.string() + "'").out);
  CHECK(a["hash"] == b["hash"]);
  // Tetrahedron V, E, F = 4, 6, 4 through P, H, P, H: (10, 24, 16), (58, 96, 40), (154, 384, 232),
  // (922, 1536, 616).
  CHECK(a["vertices"] == 922);
  CHECK(a["edges"] == 1536);
  CHECK(a["faces"] == 616);
}

TEST_CASE("mp tool: bad input and parameters give one error line and write nothing") {
  const auto out = scratch("never.obj");
  const std::string o = " -o '" + out.string() + "'";
  check_one_line_error(run("subdivide " + example("cube.obj") + " -s mhp --param pattern=H4Q" + o),
                       "at character 3", 2);
  check_one_line_error(run("subdivide " + example("cube.obj") + " -s mhp --param 'pattern=(HP'" + o),
                       "expected ')'", 2);
  check_one_line_error(run("subdivide " + example("cube.obj") + " -s mp-honeycomb --param tau=1.5" + o),
                       "tau", 2);
  check_one_line_error(run("subdivide " + example("cube.obj") + " -s mp-pushing --param tau=0" + o), "tau",
                       2);
  check_one_line_error(run("subdivide " + example("cube.obj") + " -s mp-pushing --param center=1,2" + o),
                       "center", 2);
  // A rejected value is shown as given, not rounded to an allowed one.
  const Run close_to_one =
      run("subdivide " + example("cube.obj") + " -s mp-honeycomb --param tau=1.000000001" + o);
  CHECK(close_to_one.exit_code == 2);
  CHECK(close_to_one.err == "error: mp-honeycomb: parameter tau = 1.000000001 is outside (0, 1)\n");
  Run outside = run("subdivide " + example("cube.obj") + " -s mp-honeycomb --param center=0,0,5" + o);
  check_one_line_error(outside, "not strictly inside the plane of f");
  check_one_line_error(run("subdivide '" + dented_octahedron_obj().string() + "' -s mp-pushing" + o),
                       "concave");
  check_one_line_error(run("subdivide '" + dented_octahedron_obj().string() + "' -s mhp" + o),
                       "mhp step 0 (H)");
  CHECK_FALSE(std::filesystem::exists(out));
}
#endif

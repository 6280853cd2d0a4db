// The dlfl tool on cell complexes: `subdivide -s mlca`, `convert` and `info` on .vtk files and on .obj files
// with points or curves; everything else on them is a one-line error that writes nothing.

#include <doctest/doctest.h>

#ifdef DLFL_TOOL
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tool_runner.h"

using namespace dlfl::test;

namespace {

// The unit cube as one VTK hexahedron (VTK's vertex order: bottom square, then top square,
// counter-clockwise).
std::filesystem::path unit_cube_vtk() {
  return scratch_file("cube.vtk",
                      "# vtk DataFile Version 3.0\nunit cube\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                      "POINTS 8 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                      "CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n12\n");
}

nlohmann::json info(const std::filesystem::path& path) {
  Run r = run("info '" + path.string() + "'");
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

}  // namespace

TEST_CASE("cells tool: subdivide -s mlca refines a hexahedron and info counts the cells") {
  const auto in = unit_cube_vtk();
  auto j = info(in);
  CHECK(j["vertices"] == 8);
  CHECK(j["cells_by_dimension"] == nlohmann::json({{"0", 0}, {"1", 0}, {"2", 0}, {"3", 1}}));
  // Two steps: each hexahedron into 8, so 64 cells on a 5 x 5 x 5 lattice of vertices.
  const auto out = scratch("cube2.vtk");
  REQUIRE(run("subdivide '" + in.string() + "' -s mlca -n 2 -o '" + out.string() + "'").exit_code == 0);
  j = info(out);
  CHECK(j["vertices"] == 125);
  CHECK(j["cells"] == 64);
  CHECK(j["cells_by_dimension"]["3"] == 64);
  // Averaging shrinks the lone cube symmetrically about its centre (1/2, 1/2, 1/2), and strictly.
  for (int k = 0; k < 3; ++k) {
    const double lo = j["bbox"][0][k], hi = j["bbox"][1][k];
    CHECK(lo + hi == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(lo > 0.0);
  }
}

TEST_CASE("cells tool: a curve in OBJ l lines subdivides and converts to VTK") {
  const auto in = scratch("curve.obj");
  std::ofstream(in) << "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 3 1 0\nl 1 2 3 4\n";
  const auto out = scratch("curve1.obj");
  REQUIRE(run("subdivide '" + in.string() + "' -s mlca -o '" + out.string() + "'").exit_code == 0);
  // 3 segments become 6, with one new vertex per segment: 7 vertices.
  auto j = info(out);
  CHECK(j["vertices"] == 7);
  CHECK(j["cells_by_dimension"] == nlohmann::json({{"0", 0}, {"1", 6}, {"2", 0}, {"3", 0}}));
  const auto vtk = scratch("curve1.vtk");
  REQUIRE(run("convert '" + out.string() + "' '" + vtk.string() + "' --ascii").exit_code == 0);
  CHECK(info(vtk) == j);
}

TEST_CASE("cells tool: what does not apply to a cell complex is one error line and no output") {
  const auto in = unit_cube_vtk();
  const auto out = scratch("never.vtk");
  const std::string cases[] = {
      "subdivide '" + in.string() + "' -s loop -o '" + out.string() + "'",
      "subdivide '" + in.string() + "' -s mlca --param t=0.5 -o '" + out.string() + "'",
      "subdivide '" + in.string() + "' -s mlca --log '" + scratch("log.json").string() + "' -o '" +
          out.string() + "'",
      "subdivide '" + in.string() + "' -s mlca -o '" + scratch("never.obj").string() + "'",  // hexahedra
      "convert '" + in.string() + "' '" + scratch("never.ply").string() + "'",
      "info --angles '" + in.string() + "'",
  };
  for (const std::string& args : cases) {
    CAPTURE(args);
    Run r = run(args);
    CHECK(r.exit_code == 1);
    CHECK(r.err.rfind("error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  for (const char* name : {"never.vtk", "never.obj", "never.ply", "log.json"}) {
    CHECK_FALSE(std::filesystem::exists(scratch_dir() / name));
  }
}
#endif

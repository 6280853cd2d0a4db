// Each scheme's declared closed-form counts predict what its steps make, and a run beyond 32-bit handles is
// refused before its first step.

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/schemes/scheme_registry.h>
#include "scheme_meshes.h"
#include "test_meshes.h"
#include "tool_runner.h"

using namespace dlfl;

TEST_CASE("predict_counts: every scheme's closed forms give the counts its steps make") {
  // Triangle schemes on the icosahedron, the convexity-preserving ones on the cube (convex), the rest on a
  // genus-2 surface too, so that the forms are checked off the sphere.
  const Mesh icosahedron = build_mesh(test::icosahedron_soup());
  const Mesh cube = test::cube();
  const Mesh genus2 = build_mesh(test::genus_soup(2));
  for (const SchemeSpec& spec : schemes()) {
    CAPTURE(spec.name);
    REQUIRE(spec.counts);  // every scheme declares them
    const bool triangles = spec.name == "loop" || spec.name == "sqrt3";
    const bool convex = spec.name.rfind("mp-", 0) == 0 || spec.name == "mhp";
    std::vector<const Mesh*> inputs;
    if (triangles) {
      inputs = {&icosahedron};
    } else if (convex) {
      inputs = {&cube};
    } else {
      inputs = {&cube, &genus2};
    }
    const Params params = resolve_scheme_params(spec.name, {});
    for (const Mesh* input : inputs) {
      Mesh m = *input;
      for (int step = 1; step <= 2; ++step) {
        CAPTURE(step);
        m = apply_scheme(m, spec.name, params);
        const auto predicted = predict_counts(spec.name, params, counts_of(*input), step);
        REQUIRE(predicted);
        CHECK(*predicted == counts_of(m));
      }
    }
  }
}

TEST_CASE("counts_of leaves point spheres out") {
  Mesh m = test::cube();
  const MeshCounts cube = counts_of(m);
  CHECK(cube == MeshCounts{8, 12, 6});
  m.create_vertex({5, 5, 5});
  CHECK(counts_of(m) == cube);
}

TEST_CASE("subdivide: a run beyond 32-bit handles is refused before any work, naming iterations") {
  Editor editor;
  editor.set_mesh(test::cube());
  const std::size_t logged = editor.log().size();
  // The cube's edges triple with each honeycomb step: 12 * 3^18 edges make about 9.3e9 corners.
  try {
    editor.subdivide("honeycomb", {}, 18);
    FAIL("expected a refusal");
  } catch (const ParameterError& e) {
    CHECK(e.parameter() == "iterations");
    CHECK(std::string(e.what()).find("32-bit") != std::string::npos);
  }
  CHECK(editor.mesh() == test::cube());
  CHECK(editor.log().size() == logged);
  // 12 * 3^17 edges make 3.1e9 corners, which handles still number: not refused by this check (it would run).
  const auto predicted = predict_counts("honeycomb", resolve_scheme_params("honeycomb", {}), {8, 12, 6}, 17);
  REQUIRE(predicted);
  CHECK(predicted->edges == 12ull * 129140163ull);
}

#ifdef DLFL_TOOL
TEST_CASE("tool: subdivide refuses at once a run that cannot fit, with exit 2 for handles") {
  using namespace dlfl::test;
  ScratchDir dir;
  Run r =
      run("subdivide " + example("cube.obj") + " -s honeycomb -n 20 -o '" + (dir / "x.obj").string() + "'");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("32-bit handles") != std::string::npos);
  CHECK(dir.entries().empty());

  // A run that fits the handles but not the memory (held to 1 MB): exit 1, before any work. The cube after
  // 6 honeycomb steps has 12 * 3^6 = 8748 edges, about 0.5 MB of arrays, times three and more at the peak.
  setenv("DLFL_AVAILABLE_MEMORY", "1000000", 1);
  Run memory =
      run("subdivide " + example("cube.obj") + " -s honeycomb -n 6 -o '" + (dir / "x.obj").string() + "'");
  unsetenv("DLFL_AVAILABLE_MEMORY");
  CHECK(memory.exit_code == 1);
  CHECK(memory.err.find("GiB are available") != std::string::npos);
  CHECK(dir.entries().empty());
  Run fits =
      run("subdivide " + example("cube.obj") + " -s honeycomb -n 2 -o '" + (dir / "x.obj").string() + "'");
  CHECK(fits.exit_code == 0);
}
#endif

// Editor history (exact undo/redo of operators and schemes), the native JSON format, and operation logs.

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/io/json_mesh.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/validate.h>
#include "log_helpers.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

// The error a log gets, with its op index and field.
LogError log_error(const nlohmann::json& log) {
  try {
    test::replay_json(log, "test-log");
  } catch (const LogError& e) {
    return e;
  }
  FAIL("the log replayed");
  return LogError("", 0, "", "");
}

nlohmann::json log_of(nlohmann::json ops) {
  return {{"format", "dlfl-oplog"}, {"version", 1}, {"ops", std::move(ops)}};
}

}  // namespace

TEST_CASE("history: undo of a scheme gives back M_n and redo gives back M_n+1") {
  Editor ed;
  ed.set_mesh(test::cube());
  const Mesh m0 = ed.mesh();
  ed.subdivide("honeycomb", {}, 2);
  // M_n+1 computed independently of the editor.
  const Params p = resolve_scheme_params("honeycomb", {});
  const Mesh m2 = apply_scheme(apply_scheme(m0, "honeycomb", p), "honeycomb", p);
  CHECK(ed.mesh() == m2);
  REQUIRE(ed.undo());
  CHECK(ed.mesh() == m0);
  CHECK(mesh_hash(ed.mesh()) == mesh_hash(m0));
  REQUIRE(ed.redo());
  CHECK(ed.mesh() == m2);
  REQUIRE(ed.undo());
  REQUIRE(ed.undo());  // the set_mesh
  CHECK(ed.mesh().num_vertices() == 0);
  CHECK_FALSE(ed.undo());
}

TEST_CASE("history: every operator through the editor undoes and redoes exactly") {
  Editor ed;
  ed.set_mesh(build_mesh(test::torus_soup(4, 3)));
  std::vector<Mesh> states{ed.mesh()};
  VertexId v = ed.create_vertex({1, 2, 3});
  states.push_back(ed.mesh());
  ed.insert_edge(ed.mesh().corner(v), ed.mesh().first_corner(FaceId(0)));  // dangling edge: merge
  states.push_back(ed.mesh());
  ed.insert_edge(ed.mesh().first_corner(FaceId(1)),
                 ed.mesh().next(ed.mesh().next(ed.mesh().first_corner(FaceId(1)))));
  states.push_back(ed.mesh());
  ed.delete_edge(EdgeId(3));
  states.push_back(ed.mesh());
  VertexId w = ed.subdivide_edge(EdgeId(5), {0.25, 0.5, 0.75});
  states.push_back(ed.mesh());
  ed.set_position(w, {-1, -2, -3});
  states.push_back(ed.mesh());
  ed.unsubdivide_edge(w);
  states.push_back(ed.mesh());
  std::vector<glm::dvec3> square{{0, 0, 5}, {1, 0, 5}, {1, 1, 5}, {0, 1, 5}};
  ed.create_face_manifold(square);
  states.push_back(ed.mesh());
  ed.subdivide("honeycomb");
  states.push_back(ed.mesh());
  for (std::size_t i = states.size() - 1; i > 0; --i) {
    REQUIRE(ed.undo());
    CHECK(ed.mesh() == states[i - 1]);
  }
  for (std::size_t i = 1; i < states.size(); ++i) {
    REQUIRE(ed.redo());
    CHECK(ed.mesh() == states[i]);
    CHECK(validate(ed.mesh()).valid());
  }
  CHECK_FALSE(ed.redo());
}

TEST_CASE("history: a failed operation changes nothing and is not logged") {
  Editor ed;
  ed.set_mesh(test::cube());
  const Mesh before = ed.mesh();
  const auto ops = test::log_json(ed)["ops"].size();
  CHECK_THROWS_AS(ed.delete_vertex(VertexId(0)), TopologyError);
  CHECK_THROWS_AS(ed.subdivide("honeycomb", {{"t", 2.0}}), InvalidArgument);
  CHECK_THROWS_AS(ed.subdivide("no-such-scheme"), InvalidArgument);
  CHECK_THROWS_AS(ed.subdivide("honeycomb", {{"zzz", 1.0}}), InvalidArgument);
  CHECK_THROWS_AS(ed.subdivide("honeycomb", {{"a", 0.5}, {"a0", 0.4}}), InvalidArgument);
  const std::vector<glm::dvec3> one_point{{0, 0, 0}};
  const std::vector<glm::dvec3> not_finite{{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}};
  CHECK_THROWS_AS(ed.create_face_manifold(one_point), InvalidArgument);
  CHECK_THROWS_AS(ed.create_face_manifold(not_finite), InvalidArgument);
  CHECK(ed.mesh() == before);
  CHECK(test::log_json(ed)["ops"].size() == ops);
}

TEST_CASE("history: the undo limit drops the oldest entries") {
  Editor ed(Editor::Options{false, 2});
  ed.create_vertex({0, 0, 0});
  ed.create_vertex({1, 0, 0});
  ed.create_vertex({2, 0, 0});
  CHECK(ed.undo());
  CHECK(ed.undo());
  CHECK_FALSE(ed.undo());
  CHECK(ed.mesh().num_vertices() == 1);
  // The log replays to the same state: its undo limit travels with it.
  CHECK(replay_log(log_text(ed)).mesh() == ed.mesh());
}

TEST_CASE("history: a long random session of operators and schemes and undo and redo replays exactly") {
  Editor ed;
  ed.set_mesh(build_mesh(test::genus_soup(1)));
  std::mt19937_64 rng(2024);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto point = [&] {
    std::uniform_real_distribution<double> u(-1, 1);
    return glm::dvec3(u(rng), u(rng), u(rng));
  };
  auto pick_corner = [&] {
    const Mesh& m = ed.mesh();
    for (int t = 0; t < 100; ++t) {
      CornerId c(std::uint32_t(uniform(0, int(m.corner_capacity()) - 1)));
      if (m.is_alive(c)) return c;
    }
    return CornerId();
  };
  int schemes = 0, undos = 0, redos = 0;
  for (int round = 0; round < 5000; ++round) {
    const int dice = uniform(0, 99);
    const Mesh& m = ed.mesh();
    if (dice < 10) {
      undos += ed.undo();
    } else if (dice < 18) {
      redos += ed.redo();
    } else if (dice < 21 && m.num_faces() < 1500) {
      // A constant tension: the default a0 + a1/N exceeds 1 on the 2-gons this session makes.
      ed.subdivide("honeycomb", {{"t", 0.25 + 0.5 * (uniform(0, 10) / 10.0)}, {"a", 0.6}});
      ++schemes;
    } else if (dice < 50) {
      CornerId a = pick_corner();
      if (!a.valid()) continue;
      CornerId b = a;
      for (int k = uniform(1, 5); k > 0; --k) b = m.next(b);
      if (dice % 3 == 0) b = pick_corner();
      if (!b.valid() || m.vertex(a) == m.vertex(b)) continue;
      ed.insert_edge(a, b);
    } else if (dice < 75) {
      CornerId a = pick_corner();
      if (a.valid() && m.edge(a).valid()) ed.delete_edge(m.edge(a));
    } else if (dice < 85) {
      CornerId a = pick_corner();
      if (a.valid() && m.edge(a).valid()) ed.subdivide_edge(m.edge(a), point());
    } else if (dice < 92) {
      CornerId a = pick_corner();
      if (a.valid()) ed.set_position(m.vertex(a), point());
    } else if (dice < 96) {
      ed.create_vertex(point());
    } else {
      CornerId a = pick_corner();
      if (a.valid() && m.is_point_sphere(m.vertex(a))) ed.delete_vertex(m.vertex(a));
    }
  }
  require_valid(ed.mesh());
  CHECK(schemes >= 3);
  CHECK(undos > 100);
  CHECK(redos > 20);
  // Replay through JSON text, as a file would carry it.
  const nlohmann::json log = test::log_json(ed);
  const Editor again = test::replay_json(log);
  CHECK(again.mesh() == ed.mesh());
  CHECK(mesh_hash(again.mesh()) == mesh_hash(ed.mesh()));
}

TEST_CASE("history: a self-contained log replays without the input file") {
  const auto input = test::scratch("input.obj");
  write_mesh(build_mesh(test::grid_soup(2, 2)), input);
  Editor ed(Editor::Options{true, 0});
  ed.set_mesh(read_mesh(input), input);
  ed.subdivide("honeycomb", {{"a", 0.6}});
  const nlohmann::json log = test::log_json(ed);
  std::filesystem::remove(input);
  CHECK(test::replay_json(log).mesh() == ed.mesh());
  // Without the mesh inline the same log cannot be replayed any more, and says which op and field.
  nlohmann::json bare = log;
  bare["ops"][0].erase("mesh");
  LogError e = log_error(bare);
  CHECK(e.op() == 0);
  CHECK(e.field() == "path");
}

TEST_CASE("history: every malformed log gets an error naming the op and the field") {
  const nlohmann::json ok_ops = {{{"op", "create_vertex"}, {"position", {0, 0, 0}}},
                                 {{"op", "create_vertex"}, {"position", {1, 0, 0}}}};
  CHECK_NOTHROW(test::replay_json(log_of(ok_ops)));
  {
    nlohmann::json log = log_of(ok_ops);
    log["version"] = oplog_version + 1;
    CHECK(log_error(log).field() == "version");
    CHECK(log_error(log).op() == LogError::npos);
  }
  {
    nlohmann::json log = log_of(ok_ops);
    log["format"] = "something-else";
    CHECK(log_error(log).field() == "format");
  }
  {
    nlohmann::json ops = ok_ops;
    ops.push_back({{"op", "explode"}});
    LogError e = log_error(log_of(ops));
    CHECK(e.op() == 2);
    CHECK(e.field() == "op");
    CHECK(std::string(e.what()).find("explode") != std::string::npos);
  }
  {
    nlohmann::json ops = ok_ops;
    ops.push_back({{"op", "insert_edge"}, {"corner1", 0}});
    LogError e = log_error(log_of(ops));
    CHECK(e.op() == 2);
    CHECK(e.field() == "corner2");
  }
  {
    nlohmann::json ops = ok_ops;
    ops.push_back({{"op", "insert_edge"}, {"corner1", "zero"}, {"corner2", 1}});
    LogError e = log_error(log_of(ops));
    CHECK(e.op() == 2);
    CHECK(e.field() == "corner1");
  }
  {
    nlohmann::json ops = ok_ops;
    ops.push_back({{"op", "insert_edge"}, {"corner1", 0}, {"corner2", 7}});  // no corner 7 yet
    LogError e = log_error(log_of(ops));
    CHECK(e.op() == 2);
    CHECK(e.field() == "corner2");
    CHECK(std::string(e.what()).find("c7") != std::string::npos);
  }
  {
    nlohmann::json ops = ok_ops;
    ops[1]["position"] = {1, 0};
    LogError e = log_error(log_of(ops));
    CHECK(e.op() == 1);
    CHECK(e.field() == "position");
  }
  {
    nlohmann::json ops = ok_ops;
    ops.push_back(
        {{"op", "subdivide"}, {"scheme", "honeycomb"}, {"iterations", 1}, {"params", {{"t", "x"}}}});
    LogError e = log_error(log_of(ops));
    CHECK(e.op() == 2);
  }
  {
    nlohmann::json ops = ok_ops;
    ops.push_back({{"op", "undo"}});
    ops.push_back({{"op", "undo"}});
    ops.push_back({{"op", "undo"}});
    LogError e = log_error(log_of(ops));
    CHECK(e.op() == 4);
  }
  {
    // Bad JSON in a file: an IoError, and the tool writes nothing (see the tool tests).
    const auto path = test::scratch("garbage.json");
    std::ofstream(path) << "{\"format\": \"dlfl-oplog\", \"ops\": [";
    CHECK_THROWS_AS(replay_log_file(path), IoError);
  }
}

TEST_CASE("history: the native JSON format saves and reloads a mesh exactly") {
  Mesh m = test::cube();
  CornerId c = m.first_corner(FaceId(2));
  m.insert_edge(c, m.next(c));  // a 2-gon: no polygon format can hold it
  m.delete_edge(EdgeId(4));     // a tombstone
  m.set_hole(*m.faces().begin(), true);
  m.set_position(VertexId(3), {0.1, -0.0, 1e-300});
  const auto path = test::scratch("mesh.json");
  write_mesh(m, path);
  Mesh back = read_mesh(path);
  CHECK(back == m);
  CHECK(back.edge_capacity() == m.edge_capacity());
  CHECK(std::signbit(back.position(VertexId(3)).y));
  CHECK(mesh_hash(back) == mesh_hash(m));
}

TEST_CASE("history: a broken native JSON mesh names the field") {
  nlohmann::json doc = mesh_to_json(test::tetrahedron());
  auto error_of = [](const nlohmann::json& d) {
    try {
      mesh_from_json(d, "doc");
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  {
    nlohmann::json d = doc;
    d["version"] = 9;
    CHECK(error_of(d).find("version") != std::string::npos);
  }
  {
    nlohmann::json d = doc;
    d.erase("edges");
    CHECK(error_of(d).find("'edges'") != std::string::npos);
  }
  {
    nlohmann::json d = doc;
    d["corners"][2][2] = 999;  // next out of range
    CHECK(error_of(d).find("c2") != std::string::npos);
  }
  {
    nlohmann::json d = doc;
    d["corners"][2][0] = "v";
    CHECK(error_of(d).find("corners[2][0]") != std::string::npos);
  }
  {
    nlohmann::json d = doc;
    std::swap(d["corners"][0][2], d["corners"][1][2]);  // in range, but the links no longer agree
    CHECK(error_of(d).find("not a valid DLFL") != std::string::npos);
  }
}

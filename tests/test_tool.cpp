// The dlfl tool's contract: JSON keys and values, exit codes, one-line errors, no partial outputs.

#include <doctest/doctest.h>

#ifdef DLFL_TOOL
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {

struct Run {
  int exit_code;
  std::string out;
  std::string err;
};

// Runs the tool with arguments (already shell-quoted where needed), capturing stdout and stderr.
Run run(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path() / "dlfl_tool_test";
  std::filesystem::create_directories(dir);
  const auto err_path = dir / "stderr.txt";
  const std::string cmd = std::string("'") + DLFL_TOOL + "' " + args + " 2>'" + err_path.string() + "'";
  Run r{};
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(err_path);
  r.err.assign(std::istreambuf_iterator<char>(e), {});
  return r;
}

std::string example(const char* name) {
  return std::string("'") + DLFL_SOURCE_DIR + "/examples/" + name + "'";
}

std::filesystem::path scratch(const char* name) {
  const auto dir = std::filesystem::temp_directory_path() / "dlfl_tool_test";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return dir / name;
}

}  // namespace

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
#endif

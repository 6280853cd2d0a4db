// The tool never loses a file: empty and binary inputs are refused, outputs are all or nothing, a file named
// twice is a usage error, links are written through, permissions are kept, and a stopped run leaves no
// temporary file. Also the library's FileBatch that these rest on.

#include <doctest/doctest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/mesh_io.h>
#include "test_helpers.h"
#include "tool_runner.h"

namespace fs = std::filesystem;
using namespace dlfl;
using namespace dlfl::test;

namespace {

std::string quoted(const fs::path& p) {
  std::string q = "'";
  q.append(p.string()).push_back('\'');
  return q;
}

unsigned mode_of(const fs::path& p) {
  struct stat st {};
  REQUIRE(stat(p.c_str(), &st) == 0);
  return st.st_mode & 07777;
}

}  // namespace

TEST_CASE("FileBatch: nothing is replaced until commit, and a failed stage leaves every target as it was") {
  ScratchDir dir;
  write_text(dir / "a.txt", "old a");
  write_text(dir / "b.txt", "old b");
  {
    FileBatch batch;
    batch.stage(dir / "a.txt", [](std::ostream& out) { out << "new a"; });
    CHECK(read_text(dir / "a.txt") == "old a");
    CHECK(dir.entries().size() == 3);  // a, b and a's temporary file
    CHECK_THROWS_AS(batch.stage(dir / "b.txt", [](std::ostream&) { throw TopologyError("stop"); }),
                    TopologyError);
    CHECK(batch.size() == 1);
  }  // destroyed without commit
  CHECK(read_text(dir / "a.txt") == "old a");
  CHECK(read_text(dir / "b.txt") == "old b");
  CHECK(dir.entries() == std::vector<std::string>{"a.txt", "b.txt"});

  FileBatch batch;
  batch.stage(dir / "a.txt", [](std::ostream& out) { out << "new a"; });
  batch.stage(dir / "b.txt", [](std::ostream& out) { out << "new b"; });
  batch.commit();
  CHECK(read_text(dir / "a.txt") == "new a");
  CHECK(read_text(dir / "b.txt") == "new b");
  CHECK(dir.entries() == std::vector<std::string>{"a.txt", "b.txt"});
}

TEST_CASE("FileBatch: a mesh and a second file staged together, through WriteOptions::batch") {
  ScratchDir dir;
  const Mesh cube = read_mesh(std::string(DLFL_SOURCE_DIR) + "/data/cube.obj");
  FileBatch batch;
  WriteOptions options;
  options.batch = &batch;
  write_mesh(cube, dir / "cube.ply", options);
  CHECK(!fs::exists(dir / "cube.ply"));
  batch.commit();
  CHECK(read_mesh(dir / "cube.ply") == read_mesh(std::string(DLFL_SOURCE_DIR) + "/data/cube.obj"));
}

TEST_CASE(
    "check_writable: missing folder, folder, read-only file; writing keeps the mode and follows links") {
  ScratchDir dir;
  CHECK_THROWS_WITH_AS(check_writable(dir / "no" / "x.obj"), doctest::Contains("does not exist"), IoError);
  fs::create_directory(dir / "sub");
  CHECK_THROWS_WITH_AS(check_writable(dir / "sub"), doctest::Contains("is a folder"), IoError);
  write_text(dir / "ro.txt", "keep");
  fs::permissions(dir / "ro.txt", fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  CHECK_THROWS_WITH_AS(write_atomically(dir / "ro.txt", [](std::ostream& out) { out << "x"; }),
                       doctest::Contains("read-only"), IoError);
  CHECK(read_text(dir / "ro.txt") == "keep");

  write_text(dir / "private.txt", "old");
  fs::permissions(dir / "private.txt", fs::perms::owner_read | fs::perms::owner_write);
  write_atomically(dir / "private.txt", [](std::ostream& out) { out << "new"; });
  CHECK(read_text(dir / "private.txt") == "new");
  CHECK(mode_of(dir / "private.txt") == 0600);

  fs::create_symlink("sub/target.txt", dir / "link.txt");
  CHECK(write_target(dir / "link.txt") == dir / "sub/target.txt");
  write_atomically(dir / "link.txt", [](std::ostream& out) { out << "through"; });
  CHECK(fs::is_symlink(fs::symlink_status(dir / "link.txt")));
  CHECK(read_text(dir / "sub" / "target.txt") == "through");
}

TEST_CASE("remove_temporary_files: a process stopped by SIGTERM while writing leaves no temporary file") {
  ScratchDir dir;
  write_text(dir / "out.txt", "before");
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    remove_temporary_files_on_signals();
    FileBatch batch;
    batch.stage(dir / "out.txt", [](std::ostream& out) { out << std::string(1 << 20, 'x'); });
    std::raise(SIGTERM);  // as if stopped between writing and renaming
    _exit(0);             // not reached: the handler ends the process as SIGTERM does
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(dir.entries() == std::vector<std::string>{"out.txt"});
  CHECK(read_text(dir / "out.txt") == "before");
}

TEST_CASE("read_mesh: an empty file, a file without geometry and a binary file are errors") {
  ScratchDir dir;
  for (const char* name : {"empty.obj", "empty.off", "empty.ply", "empty.json"}) {
    CAPTURE(name);
    write_text(dir / name, "");
    CHECK_THROWS_WITH_AS(read_mesh(dir / name), doctest::Contains("no vertices"), IoError);
  }
  write_text(dir / "comments.obj", "# only a comment\n\n");
  CHECK_THROWS_WITH_AS(read_mesh(dir / "comments.obj"), doctest::Contains("no vertices"), IoError);
  write_text(dir / "blank.off", "  \n\t\n");
  CHECK_THROWS_WITH_AS(read_mesh(dir / "blank.off"), doctest::Contains("no vertices"), IoError);

  // A NUL on line 3 (1-based, as an editor counts).
  write_text(dir / "nul.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1\0 0\nf 1 2 3\n", 33));
  CHECK_THROWS_WITH_AS(read_mesh(dir / "nul.obj"), doctest::Contains("binary data at line 3"), IoError);
  std::mt19937 random(7);
  std::string noise(4096, '\0');
  for (char& c : noise) c = static_cast<char>(random() & 0xff);
  write_text(dir / "noise.obj", noise);
  CHECK_THROWS_WITH_AS(read_mesh(dir / "noise.obj"), doctest::Contains("binary data at line"), IoError);
  // UTF-8 in a comment is text.
  write_text(dir / "utf8.obj", "# caf\xc3\xa9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK(read_mesh(dir / "utf8.obj").num_vertices() == 3);
}

TEST_CASE("read_mesh: messages number faces from 1 and vertices as the file does, with the handle beside") {
  ScratchDir dir;
  // The second f line (line 6) runs 1 -> 2 as the first does: the OBJ's vertices 1 and 2, its face 2.
  write_text(dir / "twice.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
  CHECK_THROWS_WITH_AS(
      read_mesh(dir / "twice.obj"),
      doctest::Contains("twice.obj:6: face 2 (f1): edge 1-2 is also used in the same direction "
                        "by face 1"),
      IoError);
  // OFF indices start at 0, so its vertices keep their numbers; faces still count from 1.
  write_text(dir / "twice.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n");
  CHECK_THROWS_WITH_AS(read_mesh(dir / "twice.off"),
                       doctest::Contains("twice.off:8: face 2 (f1): edge 0-1 is also used"), IoError);
  write_text(dir / "repeat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 3 1\n");
  CHECK_THROWS_WITH_AS(read_mesh(dir / "repeat.obj"),
                       doctest::Contains("repeat.obj:5: face 2 (f1): uses vertex 3 twice in a row"), IoError);
}

TEST_CASE("write_mesh: an empty mesh makes no file") {
  ScratchDir dir;
  CHECK_THROWS_WITH_AS(write_mesh(Mesh(), dir / "e.obj"), doctest::Contains("no vertices"), IoError);
  CHECK(dir.entries().empty());
}

TEST_CASE("validate_mesh_file: a .json mesh with a broken structure lists every violation") {
  ScratchDir dir;
  const Mesh cube = read_mesh(std::string(DLFL_SOURCE_DIR) + "/data/cube.obj");
  write_mesh(cube, dir / "cube.json");
  nlohmann::json doc = nlohmann::json::parse(read_text(dir / "cube.json"));
  // Two faces claim 5 corners where their cycles have 4: each is a face_size violation, and so is the total
  // of the sizes, 26 for 24 corners.
  doc["faces"][0][1] = 5;
  doc["faces"][1][1] = 5;
  write_text(dir / "broken.json", doc.dump());
  CHECK_THROWS_AS(read_mesh(dir / "broken.json"), IoError);
  const ValidationReport report = validate_mesh_file(dir / "broken.json");
  CHECK(!report.valid());
  std::vector<std::string> faces;
  for (const Violation& v : report.violations)
    if (v.code == ViolationCode::face_size) faces.push_back(v.element);
  CHECK(faces == std::vector<std::string>{"f0", "f1", "mesh"});
}

#ifdef DLFL_TOOL
TEST_CASE("tool: empty and binary inputs fail with exit 1 and write nothing") {
  ScratchDir dir;
  write_text(dir / "empty.obj", "");
  Run info = run("info " + quoted(dir / "empty.obj"));
  CHECK(info.exit_code == 1);
  CHECK(info.err.find("no vertices") != std::string::npos);
  Run convert = run("convert " + quoted(dir / "empty.obj") + " " + quoted(dir / "out.obj"));
  CHECK(convert.exit_code == 1);
  CHECK(!fs::exists(dir / "out.obj"));
  write_text(dir / "bytes.obj", std::string("\x01\x02\x03garbage", 10));
  Run binary = run("info " + quoted(dir / "bytes.obj"));
  CHECK(binary.exit_code == 1);
  CHECK(binary.err.find("binary data at line 1") != std::string::npos);
}

TEST_CASE("tool: the mesh and its log are written both or neither") {
  ScratchDir dir;
  Run r = run("subdivide " + example("cube.obj") + " -s honeycomb -o " + quoted(dir / "x.obj") + " --log " +
              quoted(dir / "nodir" / "l.json"));
  CHECK(r.exit_code == 1);
  CHECK(dir.entries().empty());
  Run e = run("edit " + example("cube.obj") + " --op 'subdivide scheme=honeycomb' -o " +
              quoted(dir / "x.obj") + " --log " + quoted(dir / "nodir" / "l.json"));
  CHECK(e.exit_code == 1);
  CHECK(dir.entries().empty());
  Run ok = run("subdivide " + example("cube.obj") + " -s honeycomb -o " + quoted(dir / "x.obj") + " --log " +
               quoted(dir / "l.json"));
  CHECK(ok.exit_code == 0);
  CHECK(dir.entries() == std::vector<std::string>{"l.json", "x.obj"});
}

TEST_CASE("tool: a file named twice is a usage error (exit 2) and is left untouched") {
  ScratchDir dir;
  fs::copy_file(std::string(DLFL_SOURCE_DIR) + "/data/cube.obj", dir / "in.obj");
  const std::string original = read_text(dir / "in.obj");
  fs::create_directory(dir / "sub");
  fs::create_symlink("../in.obj", dir / "sub" / "alias.obj");
  const std::string in = quoted(dir / "in.obj");
  for (const std::string& args :
       {"subdivide " + in + " -s honeycomb -o " + in, "convert " + in + " " + in,
        "convert " + in + " " + quoted(dir / "sub" / ".." / "in.obj"),
        "convert " + in + " " + quoted(dir / "sub" / "alias.obj"),
        "subdivide " + in + " -s honeycomb -o " + quoted(dir / "a.obj") + " --log " + quoted(dir / "a.obj"),
        "edit " + in + " --op 'delete_edge edge=0' -o " + quoted(dir / "sub" / "alias.obj")}) {
    CAPTURE(args);
    Run r = run(args);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("the same file") != std::string::npos);
    CHECK(read_text(dir / "in.obj") == original);
    CHECK(!fs::exists(dir / "a.obj"));
  }
}

TEST_CASE("tool: links are written through, modes are kept, a read-only output is refused before any work") {
  ScratchDir dir;
  const std::string cube = example("cube.obj");
  fs::create_directory(dir / "real");
  fs::create_symlink("real/target.obj", dir / "link.obj");
  CHECK(run("convert " + cube + " " + quoted(dir / "link.obj")).exit_code == 0);
  CHECK(fs::is_symlink(fs::symlink_status(dir / "link.obj")));
  CHECK(read_mesh(dir / "real" / "target.obj").num_faces() == 6);

  write_text(dir / "mode.obj", "old");
  fs::permissions(dir / "mode.obj", fs::perms::owner_read | fs::perms::owner_write);
  CHECK(run("convert " + cube + " " + quoted(dir / "mode.obj")).exit_code == 0);
  CHECK(mode_of(dir / "mode.obj") == 0600);
  CHECK(read_mesh(dir / "mode.obj").num_faces() == 6);

  write_text(dir / "ro.obj", "keep");
  fs::permissions(dir / "ro.obj", fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  Run r = run("subdivide " + cube + " -s honeycomb -n 2 -o " + quoted(dir / "ro.obj"));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("read-only") != std::string::npos);
  CHECK(read_text(dir / "ro.obj") == "keep");
  CHECK(mode_of(dir / "ro.obj") == 0444);
}

TEST_CASE("tool: check lists the violations of a broken .json mesh; --version prints the version") {
  ScratchDir dir;
  REQUIRE(run("convert " + example("cube.obj") + " " + quoted(dir / "cube.json")).exit_code == 0);
  nlohmann::json doc = nlohmann::json::parse(read_text(dir / "cube.json"));
  doc["faces"][2][1] = 3;
  write_text(dir / "broken.json", doc.dump());
  Run r = run("check " + quoted(dir / "broken.json"));
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("face_size") != std::string::npos);
  CHECK(run("check --help").out.find(".json") != std::string::npos);

  Run v = run("--version");
  CHECK(v.exit_code == 0);
  CHECK(v.out.rfind("dlfl ", 0) == 0);
  CHECK(std::count(v.out.begin(), v.out.end(), '.') == 2);  // MAJOR.MINOR.PATCH
}
#endif

#ifdef DLFL_TOOL
#include <pty.h>

namespace {

// Runs the tool on a pseudo-terminal (so that stderr is a terminal) and returns all it printed there.
std::string run_on_terminal(const std::vector<std::string>& args) {
  int master = -1;
  const pid_t child = forkpty(&master, nullptr, nullptr, nullptr);
  REQUIRE(child >= 0);
  if (child == 0) {
    setenv("DLFL_PROGRESS_AFTER", "0", 1);
    std::vector<char*> argv{const_cast<char*>(DLFL_TOOL)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(DLFL_TOOL, argv.data());
    _exit(127);
  }
  std::string out;
  char buffer[4096];
  for (ssize_t n; (n = read(master, buffer, sizeof buffer)) > 0;)
    out.append(buffer, static_cast<std::size_t>(n));
  int status = 0;
  waitpid(child, &status, 0);
  close(master);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  return out;
}

}  // namespace

TEST_CASE("tool: a progress bar on a terminal, -v lines, --quiet silences both, and no bar off a terminal") {
  ScratchDir dir;
  const std::string cube = std::string(DLFL_SOURCE_DIR) + "/data/cube.obj";
  const std::string out = (dir / "x.ply").string();
  const std::string bar = run_on_terminal({"subdivide", cube, "-s", "honeycomb", "-n", "2", "-o", out});
  CHECK(bar.find("\rhoneycomb step 1/2 [") != std::string::npos);
  CHECK(bar.find("\rhoneycomb step 2/2 [") != std::string::npos);
  CHECK(bar.find("%") != std::string::npos);
  const std::string quiet =
      run_on_terminal({"subdivide", cube, "-s", "honeycomb", "-n", "2", "-o", out, "-v", "--quiet"});
  CHECK(quiet.empty());

  // Off a terminal: -v gives one line per file and step, and never a bar.
  Run verbose = run("subdivide " + example("cube.obj") + " -s honeycomb -n 2 -o '" + out + "' -v");
  CHECK(verbose.exit_code == 0);
  CHECK(verbose.err.find('\r') == std::string::npos);
  CHECK(verbose.err.find("read ") == 0);
  CHECK(verbose.err.find("honeycomb step 1/2: 24 vertices, 36 edges, 14 faces in ") != std::string::npos);
  CHECK(verbose.err.find("honeycomb step 2/2: 72 vertices, 108 edges, 38 faces in ") != std::string::npos);
  CHECK(std::count(verbose.err.begin(), verbose.err.end(), '\n') == 4);  // read, two steps, write
  CHECK(run("subdivide " + example("cube.obj") + " -s honeycomb -o '" + out + "' -v -q").err.empty());
}
#endif

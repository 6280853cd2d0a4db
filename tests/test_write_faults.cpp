// Write faults: a disk that fills up while a file is written. A child process gets a file-size limit
// (RLIMIT_FSIZE, with SIGXFSZ ignored), so every write past it fails with EFBIG as on a full disk, without
// root or a special file system. Each format must then fail with IoError, leave the previous file untouched
// and leave no temporary file behind.

#include <doctest/doctest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <functional>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/cells/cell_io.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/io/mesh_io.h>
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

// Runs `write` in a child whose files may not grow past `limit` bytes. 0: it threw IoError; 1: it returned;
// 2: it threw something else.
int exit_of_limited_write(std::size_t limit, const std::function<void()>& write) {
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit small{limit, limit};
    if (setrlimit(RLIMIT_FSIZE, &small) != 0) _exit(3);
    int code = 1;
    try {
      write();
    } catch (const IoError&) {
      code = 0;
    } catch (...) {
      code = 2;
    }
    _exit(code);
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

}  // namespace

TEST_CASE("write faults: a full disk while writing any format leaves the old file and no temporary file") {
  const Mesh torus = build_mesh(torus_soup(40, 40));  // 1600 quads: every format takes well over 4 KiB
  Editor editor;
  editor.set_mesh(torus);
  editor.subdivide("catmull-clark");
  const CellComplex quads = quads_of(torus_soup(40, 40));
  const std::string previous = "the previous file, which must survive\n";
  const std::size_t limit = 4096;
  struct Case {
    std::string file;
    std::function<void(const std::filesystem::path&)> write;
  };
  const std::vector<Case> cases = {
      {"mesh.obj", [&](const auto& p) { write_mesh(editor.mesh(), p); }},
      {"mesh.off", [&](const auto& p) { write_mesh(editor.mesh(), p); }},
      {"mesh.ply", [&](const auto& p) { write_mesh(editor.mesh(), p); }},
      {"ascii.ply",
       [&](const auto& p) {
         WriteOptions ascii;
         ascii.binary = false;
         write_mesh(editor.mesh(), p, ascii);
       }},
      {"mesh.json", [&](const auto& p) { write_mesh(editor.mesh(), p); }},
      {"session.log.json", [&](const auto& p) { write_log(editor, p); }},
      {"cells.vtk", [&](const auto& p) { write_cell_complex(quads, p); }},
      {"cells.obj", [&](const auto& p) { write_cell_complex(quads, p); }},
  };
  for (const Case& c : cases) {
    CAPTURE(c.file);
    ScratchDir dir;
    write_text(dir / c.file, previous);
    CHECK(exit_of_limited_write(limit, [&] { c.write(dir / c.file); }) == 0);
    CHECK(read_text(dir / c.file) == previous);
    CHECK(dir.entries() == std::vector<std::string>{c.file});
    // The same write without the limit succeeds, so the limit was what failed it.
    CHECK(exit_of_limited_write(RLIM_INFINITY, [&] { c.write(dir / c.file); }) == 1);
    CHECK(read_text(dir / c.file) != previous);
  }
}

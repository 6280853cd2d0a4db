// Modeling benchmark: local operations (extrude_face, connect_edges, collapse_edge, stellate_face, drawn in
// turn at random places) applied to a closed quad torus of about 1M faces. Each costs the size of what it
// touches, so the rate must not fall as the mesh grows; it is reported per kind, for the operations applied
// by name (`apply_operation`, parameters checked from the declarations) and through an Editor (each one an
// undo entry).
// Usage: dlfl_bench_modeling [operations=100000] [faces=1000000] [seed=1]

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/operations/operation.h>
#include <dlfl/validate.h>
#include "bench_meshes.h"
#include "bench_util.h"

using namespace dlfl;

namespace {

constexpr const char* kinds[] = {"extrude_face", "connect_edges", "collapse_edge", "stellate_face"};

// A live element of the kind, drawn uniformly among the handles ever assigned (removed ones are skipped).
template <class H>
H live(const Mesh& m, std::mt19937& random) {
  std::uniform_int_distribution<std::uint32_t> pick(0, m.capacity(element_kind_v<H>) - 1);
  for (;;) {
    const H h(pick(random));
    if (m.is_alive(h)) return h;
  }
}

// A surface face with edges: where extrude_face and stellate_face apply.
FaceId surface_face(const Mesh& m, std::mt19937& random) {
  for (;;) {
    const FaceId f = live<FaceId>(m, random);
    if (!m.is_hole(f) && m.size(f) >= 3) return f;
  }
}

Params params_for(const std::string& kind, const Mesh& m, std::mt19937& random) {
  if (kind == "connect_edges") {
    // Two corners drawn anywhere: on a large torus they lie in different faces far apart, so the bridge
    // adds a handle.
    return {{"corner1", live<CornerId>(m, random)}, {"corner2", live<CornerId>(m, random)}};
  }
  if (kind == "collapse_edge") return {{"edge", live<EdgeId>(m, random)}};
  return {{"face", surface_face(m, random)}};
}

struct Tally {
  long applied = 0;
  long refused = 0;
  double seconds = 0;
};

// Applies the operations to `session.mesh()` through `session.apply(kind, params)`.
template <class Session>
void run(const char* title, long operations, std::uint32_t seed, Session& session) {
  std::mt19937 random(seed);
  std::map<std::string, Tally> tally;
  double first = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < operations; ++i) {
    const std::string kind = kinds[i % 4];
    const Params params = params_for(kind, session.mesh(), random);
    const auto s = std::chrono::steady_clock::now();
    Tally& t = tally[kind];
    try {
      session.apply(kind, params);
      ++t.applied;
    } catch (const ParameterError&) {
      ++t.refused;  // a collapse that the link condition refuses, a bridge of two corners of one face
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count();
    // The first change of a freshly built mesh grows its arrays (one O(size) copy, as any appending
    // container): reported on its own, so that the rates below are those of the operations.
    if (i == 0) {
      first = seconds;
    } else {
      t.seconds += seconds;
    }
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s: %ld operations in %.3f s, %.0f operations per second (%zu faces after)\n", title,
              operations, total, double(operations) / total, session.mesh().num_faces());
  std::printf("  the first operation, which grows the mesh's arrays: %.3f s\n", first);
  for (const auto& [kind, t] : tally) {
    std::printf("  %-14s %7ld applied %6ld refused  %9.0f per second\n", kind.c_str(), t.applied, t.refused,
                double(t.applied + t.refused - (kind == kinds[0])) / t.seconds);
  }
  std::printf("  valid after: %s\n", validate(session.mesh()).valid() ? "yes" : "NO");
  std::fflush(stdout);
}

// A mesh changed by name, with no history.
struct DirectSession {
  Mesh m;
  const Mesh& mesh() const { return m; }
  void apply(const std::string& kind, const Params& p) { apply_operation(m, kind, p); }
};

// An editor: each operation is an undo entry.
struct EditorSession {
  Editor editor;
  const Mesh& mesh() const { return editor.mesh(); }
  void apply(const std::string& kind, const Params& p) { editor.apply(kind, p); }
};

}  // namespace

int main(int argc, char** argv) {
  const long operations = argc > 1 ? std::stol(argv[1]) : 100000;
  const long faces = argc > 2 ? std::stol(argv[2]) : 1000000;
  const auto seed = static_cast<std::uint32_t>(argc > 3 ? std::stoul(argv[3]) : 1);
  const int side = int(std::lround(std::sqrt(double(faces))));
  const Mesh start = build_mesh(bench::torus_soup(side, side));
  std::printf("closed quad torus %d x %d = %zu faces, %ld operations drawn in turn from:", side, side,
              start.num_faces(), operations);
  for (const char* k : kinds) std::printf(" %s", k);
  std::printf("\n");

  DirectSession direct{start};
  run("by name (apply_operation)", operations, seed, direct);
  EditorSession editing;
  editing.editor.set_mesh(start);
  run("through an Editor (undo kept)", operations, seed, editing);
  return 0;
}

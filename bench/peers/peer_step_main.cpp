// dlfl_peer_step LIBRARY SCHEME N: one cold step, the unit of dlfl_bench_peers. Builds the n x n torus grid
// of the scheme (peer_schemes.h) in LIBRARY (dlfl, cgal or openmesh), times one step alone and prints its
// report (step_report.h). Each run is a fresh process, so no step finds memory or caches warmed by another.
// Exits with 3 if the library has no such scheme, 2 on bad arguments.

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "bench_meshes.h"
#include "peer_steps.h"
#include "step_report.h"

using namespace dlfl::bench;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: dlfl_peer_step dlfl|cgal|openmesh SCHEME N\n");
    return 2;
  }
  const std::string library = argv[1];
  const auto scheme = parse_scheme(argv[2]);
  const long n = std::atol(argv[3]);
  if (!scheme || n < 3 || (library != "dlfl" && library != "cgal" && library != "openmesh")) {
    std::fprintf(stderr, "dlfl_peer_step: bad arguments\n");
    return 2;
  }
  try {
    const dlfl::PolygonSoup input = torus_soup(int(n), int(n), takes_triangles(*scheme));
    const auto result = library == "dlfl"   ? dlfl_step(*scheme, input)
                        : library == "cgal" ? cgal_step(*scheme, input)
                                            : openmesh_step(*scheme, input);
    if (!result) return scheme_unavailable;
    std::fputs(format_report(*result).c_str(), stdout);
    std::fflush(stdout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dlfl_peer_step: %s\n", e.what());
    return 1;
  }
  return 0;
}

// The table of docs/lateral_artifacts.md: concave edges (and the worst bend, degrees) and the mean dihedral
// angle after 1 to 5 honeycomb steps, plain and with planarize=1, over convex shapes with flat sides and two
// smooth shapes. Usage: dlfl_bench_lateral [steps=5]

#include <cstdio>
#include <string>
#include <vector>

#include <dlfl/analysis/concave_edges.h>
#include <dlfl/build_mesh.h>
#include <dlfl/operations/hexagonalize.h>
#include <dlfl/schemes/honeycomb.h>
#include "lateral_meshes.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

struct Shape {
  std::string name;
  PolygonSoup soup;
};

std::vector<Shape> shapes() {
  std::vector<Shape> out;
  for (int n : {4, 5, 6, 7, 8}) {
    for (int rows : {1, 2, 3, 4, 5, 6}) {
      out.push_back(
          {std::to_string(n) + "-prism, " + std::to_string(rows) + " rows", test::prism_rows_soup(n, rows)});
    }
  }
  out.push_back({"box 2x2x2 grid", test::box_grid_soup(2, 2, 2)});
  out.push_back({"box 2x3x4 grid", test::box_grid_soup(2, 3, 4)});
  out.push_back({"cube, faces split in 4 triangles", test::split_around_centroids(test::cube_soup())});
  out.push_back({"octahedron, faces split in 3", test::split_around_centroids(test::octahedron_soup())});
  out.push_back({"icosahedron", test::icosahedron_soup()});
  out.push_back({"torus 8x6", test::torus_soup(8, 6)});
  out.push_back({"torus 8x5", test::torus_soup(8, 5)});
  return out;
}

std::string cell(const ConcaveEdges& c) {
  char text[64];
  std::snprintf(text, sizeof text, "%zu (%.2f) %.2f", c.concave, c.worst_concave_degrees,
                c.mean_dihedral_degrees);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::stoi(argv[1]) : 5;
  std::printf("Each cell: concave edges (worst bend, degrees) mean dihedral angle (degrees)\n\n");
  std::printf("| shape | rule |");
  for (int s = 1; s <= steps; ++s) std::printf(" step %d |", s);
  std::printf("\n|---|---|");
  for (int s = 1; s <= steps; ++s) std::printf("---|");
  std::printf("\n");
  for (const Shape& shape : shapes()) {
    const Mesh input = build_mesh(shape.soup);
    for (const char* rule : {"plain", "planarize=1", "hexagonalize"}) {
      HoneycombParams p;
      p.planarize = rule == std::string("planarize=1");
      Mesh m = rule == std::string("hexagonalize") ? hexagonalize(input) : input;
      std::printf("| %s | %s |", shape.name.c_str(), rule);
      for (int s = 1; s <= steps; ++s) {
        m = honeycomb(m, p);
        std::printf(" %s |", cell(concave_edges(m)).c_str());
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  }
}

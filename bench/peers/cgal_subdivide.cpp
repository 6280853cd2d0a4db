// cgal_subdivide IN OUT: one Catmull-Clark step in CGAL 5.5, file to file, as `dlfl subdivide IN -s
// catmull-clark -o OUT` does; the peer of the tool in dlfl_bench_end_to_end. Reads and writes with CGAL's
// IO by extension (.ply, .obj, .off): PLY binary, OBJ with 17 significant digits so that positions round-trip
// as the tool's do. Exits with 1 on a read or write failure.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#include <cstdio>

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: cgal_subdivide IN OUT\n");
    return 2;
  }
  SurfaceMesh mesh;
  if (!CGAL::IO::read_polygon_mesh(argv[1], mesh)) {
    std::fprintf(stderr, "cgal_subdivide: cannot read %s\n", argv[1]);
    return 1;
  }
  CGAL::Subdivision_method_3::CatmullClark_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
  if (!CGAL::IO::write_polygon_mesh(argv[2], mesh,
                                    CGAL::parameters::use_binary_mode(true).stream_precision(17))) {
    std::fprintf(stderr, "cgal_subdivide: cannot write %s\n", argv[2]);
    return 1;
  }
  return 0;
}

// openmesh_subdivide IN OUT: one Catmull-Clark step in OpenMesh, file to file, as `dlfl subdivide IN -s
// catmull-clark -o OUT` does; the peer of the tool in dlfl_bench_end_to_end. Reads and writes with OpenMesh's
// IO by extension: PLY binary, OBJ with 17 significant digits. OpenMesh 9.0's writers convert positions to
// float whatever the mesh's point type, so its PLY output holds 12 bytes a vertex where the others hold 24.
// Exits with 1 on a read or write failure.

#include <OpenMesh/Core/IO/MeshIO.hh>  // before the mesh types, as OpenMesh requires
#include <OpenMesh/Core/System/omstream.hh>

#include "openmesh_types.h"  // before the subdivider, which needs the mesh types declared

#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: openmesh_subdivide IN OUT\n");
    return 2;
  }
  omlog().disable();  // "[OBJWriter] : write file" and the like
  dlfl::bench::OmPolyMesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, argv[1])) {
    std::fprintf(stderr, "openmesh_subdivide: cannot read %s\n", argv[1]);
    return 1;
  }
  OpenMesh::Subdivider::Uniform::CatmullClarkT<dlfl::bench::OmPolyMesh> subdivider;
  subdivider(mesh, 1);
  const std::string out = argv[2];
  const bool ply = out.size() > 4 && out.compare(out.size() - 4, 4, ".ply") == 0;
  const OpenMesh::IO::Options options = ply ? OpenMesh::IO::Options::Binary : OpenMesh::IO::Options::Default;
  if (!OpenMesh::IO::write_mesh(mesh, out, options, 17)) {
    std::fprintf(stderr, "openmesh_subdivide: cannot write %s\n", argv[2]);
    return 1;
  }
  return 0;
}

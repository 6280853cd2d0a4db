// dlfl info MESH: one JSON object describing the mesh (dlfl/analysis/mesh_info.h, shared with the Python
// binding's dlfl.info).

#include <iostream>

#include <dlfl/analysis/mesh_info.h>
#include <dlfl/cells/cell_info.h>
#include <dlfl/cells/cell_io.h>
#include <dlfl/errors.h>
#include <dlfl/io/mesh_io.h>
#include "commands.h"

namespace dlfl::tool {

Action add_info(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Print counts, topology, histograms, bounding box and hash as JSON");
  struct Args {
    std::string path;
    bool angles = false;
    bool shape = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("MESH", a->path,
                  "Mesh file (.obj, .off, .ply, .stl, .json), or cell complex (.vtk, .obj with p or l lines)")
      ->required();
  cmd->add_flag(
      "--angles", a->angles,
      "Add \"angles\": max and mean edge, vertex and face angles (degrees, Meng-Prautzsch definition "
      "2.3) and whether the mesh is a strictly convex polyhedron around its vertex centroid");
  cmd->add_flag("--shape", a->shape,
                "Add, for a closed mesh, \"concave_edges\" and \"worst_concave_degrees\" (degrees): the "
                "lateral-artifact measure of docs/lateral_artifacts.md");
  return [a] {
    if (is_cell_complex_file(a->path)) {
      if (a->angles || a->shape) {
        throw InvalidArgument(std::string(a->angles ? "--angles" : "--shape") + " measures polyhedra; " +
                              a->path + " is a cell complex");
      }
      std::cout << cell_complex_info_json(read_cell_complex(a->path)) << "\n";
      return ok;
    }
    std::cout << mesh_info_json(read_mesh(a->path), {.angles = a->angles, .shape = a->shape}) << "\n";
    return ok;
  };
}

}  // namespace dlfl::tool

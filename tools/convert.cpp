// dlfl convert IN OUT: format by extension. Cell complexes (.vtk, .obj with points or curves) convert between
// .vtk and .obj.

#include <dlfl/cells/cell_io.h>
#include <dlfl/io/mesh_io.h>
#include "commands.h"
#include "feedback.h"
#include "file_checks.h"

namespace dlfl::tool {

Action add_convert(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "convert",
      "Convert a mesh between OBJ, OFF, PLY, STL and JSON (or to glTF, .glb), or a cell complex between "
      "VTK and OBJ (format by extension)");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto ascii = std::make_shared<bool>(false);
  cmd->add_option("IN", *in, "Input mesh")->required();
  cmd->add_option("OUT", *out, "Output mesh")->required();
  cmd->add_flag("--ascii", *ascii, "Write PLY, STL or VTK as ASCII instead of binary");
  return [in, out, ascii] {
    check_files({{"IN", *in}}, {{"OUT", *out}});
    if (is_cell_complex_file(*in)) {
      CellWriteOptions options;
      options.binary_vtk = !*ascii;
      write_cell_complex(read_cell_complex(*in), *out, options);
      return ok;
    }
    WriteOptions options;
    options.binary = !*ascii;
    FileReport reading("read", *in);
    const Mesh mesh = read_mesh(*in);
    reading.done(mesh);
    FileReport writing("write", *out);
    write_mesh(mesh, *out, options);
    writing.done(mesh);
    return ok;
  };
}

}  // namespace dlfl::tool

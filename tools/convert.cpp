// dlfl convert IN OUT: format by extension.

#include "commands.h"
#include "io/mesh_io.h"

namespace dlfl::tool {

Action add_convert(CLI::App& app) {
  auto* cmd = app.add_subcommand("convert", "Convert a mesh between OBJ, OFF and PLY (format by extension)");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto ascii = std::make_shared<bool>(false);
  cmd->add_option("IN", *in, "Input mesh")->required();
  cmd->add_option("OUT", *out, "Output mesh")->required();
  cmd->add_flag("--ascii", *ascii, "Write PLY as ASCII instead of binary little-endian");
  return [in, out, ascii] {
    WriteOptions options;
    options.binary_ply = !*ascii;
    write_mesh(read_mesh(*in), *out, options);
    return ok;
  };
}

}  // namespace dlfl::tool

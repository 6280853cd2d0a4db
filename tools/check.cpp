// dlfl check MESH: run the consistency validator.

#include <iostream>

#include <dlfl/io/mesh_io.h>
#include <dlfl/validate.h>
#include "commands.h"

namespace dlfl::tool {

Action add_check(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("check", "Validate the DLFL structure; exit 0 if valid, 1 with the violations");
  auto path = std::make_shared<std::string>();
  cmd->add_option(
         "MESH", *path,
         "Mesh file (.obj, .off, .ply, .stl, .json). A .json file may hold any DLFL state: every violation "
         "is listed. The other formats are refused by their reader with the line at fault")
      ->required();
  return [path] {
    const ValidationReport report = validate_mesh_file(*path);
    if (report.valid()) {
      std::cout << "valid: " << report.components.size() << " component(s)\n";
      return ok;
    }
    for (const auto& v : report.violations) {
      std::cout << to_string(v.code) << " " << v.element << ": " << v.message << "\n";
    }
    if (report.violation_count > report.violations.size()) {
      std::cout << "... " << report.violation_count - report.violations.size() << " more\n";
    }
    return failure;
  };
}

}  // namespace dlfl::tool

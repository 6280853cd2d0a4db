// dlfl ops [NAME] [--json]: the registered operations with their parameters, types and defaults.

#include <iostream>
#include <string>

#include <dlfl/operations/operation.h>
#include <dlfl/operations/spec_json.h>
#include "commands.h"
#include "spec_listing.h"

namespace dlfl::tool {
namespace {

void print(const OperationSpec& op) {
  std::cout << op.name << "  (" << to_string(op.kind) << ")  " << op.doc << "\n";
  if (!op.counts.empty()) std::cout << "  counts: " << op.counts << "\n";
  std::cout << param_lines(op.params);
}

}  // namespace

Action add_ops(CLI::App& app) {
  auto* cmd = app.add_subcommand("ops", "List the operations (for edit and logs) with their parameters");
  auto name = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("NAME", *name, "Show only this operation");
  cmd->add_flag("--json", *json, "Machine-readable listing");
  return [name, json] {
    if (!name->empty()) {
      const OperationSpec& op = find_operation(*name);  // unknown: a usage error with a suggestion
      if (*json) {
        std::cout << to_json(op, 1) << "\n";
      } else {
        print(op);
      }
      return ok;
    }
    if (*json) {
      std::cout << operations_json(1) << "\n";
      return ok;
    }
    bool first = true;
    for (const auto& op : operations()) {
      if (!first) std::cout << "\n";
      first = false;
      print(op);
    }
    return ok;
  };
}

}  // namespace dlfl::tool

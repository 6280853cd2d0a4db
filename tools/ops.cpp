// dlfl ops [NAME] [--json]: the registered operations with their parameters, types and defaults.

#include <iostream>
#include <string>

#include <dlfl/detail/enum_names.h>
#include <dlfl/operations/operation.h>
#include "commands.h"
#include "spec_listing.h"

namespace dlfl::tool {
namespace {

const char* kind_name(OperationSpec::Kind kind) {
  static constexpr const char* names[] = {"edit", "replace", "history"};
  static_assert(std::size(names) == std::size_t(OperationSpec::Kind::history) + 1,
                "a name per enumerator, in order");
  return detail::name_at(kind, names, "?");
}

nlohmann::ordered_json op_json(const OperationSpec& op) {
  nlohmann::ordered_json params = nlohmann::ordered_json::array();
  for (const auto& p : op.params) params.push_back(param_json(p));
  return {{"name", op.name},
          {"kind", kind_name(op.kind)},
          {"doc", op.doc},
          {"counts", op.counts},
          {"params", params}};
}

void print(const OperationSpec& op) {
  std::cout << op.name << "  (" << kind_name(op.kind) << ")  " << op.doc << "\n";
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
        std::cout << op_json(op).dump(1) << "\n";
      } else {
        print(op);
      }
      return ok;
    }
    if (*json) {
      nlohmann::ordered_json all = nlohmann::ordered_json::array();
      for (const auto& op : operations()) all.push_back(op_json(op));
      std::cout << all.dump(1) << "\n";
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

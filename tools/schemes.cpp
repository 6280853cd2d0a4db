// dlfl schemes [NAME] [--json]: the registered schemes with their parameters, read from the scheme table (the
// same declarations that `subdivide --param` is checked against).

#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/operations/spec_json.h>
#include <dlfl/schemes/scheme_registry.h>
#include "commands.h"
#include "spec_listing.h"

namespace dlfl::tool {
namespace {

void print_scheme(const SchemeSpec& s) {
  std::cout << s.name << ": " << s.doc << "\n" << param_lines(s.params);
}

}  // namespace

Action add_schemes(CLI::App& app) {
  auto* cmd = app.add_subcommand("schemes", "List the subdivision schemes and their parameters");
  struct Args {
    std::string name;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("NAME", a->name, "Show this scheme only");
  cmd->add_flag("--json", a->json,
                "Print a JSON array [{name, doc, params: [{name, type, default, range, keywords, doc, "
                "optional}]}]");
  return [a]() -> int {
    std::vector<const SchemeSpec*> shown;
    if (a->name.empty()) {
      for (const SchemeSpec& s : schemes()) shown.push_back(&s);
    } else {
      try {
        shown.push_back(&find_scheme(a->name));
      } catch (const UnknownNameError& e) {
        std::cerr << "error: " << e.what() << "\n";  // a name that is not a scheme: a usage error
        return usage;
      }
    }
    if (a->json) {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const SchemeSpec* s : shown) list.push_back(nlohmann::ordered_json::parse(to_json(*s)));
      std::cout << list.dump(2) << "\n";
      return ok;
    }
    for (std::size_t i = 0; i < shown.size(); ++i) {
      if (i > 0) std::cout << "\n";
      print_scheme(*shown[i]);
    }
    return ok;
  };
}

}  // namespace dlfl::tool

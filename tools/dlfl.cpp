// dlfl: inspect, check, convert and subdivide DLFL meshes, and replay operation logs. Errors print one line
// "error: ..." on stderr; exit 2 for usage errors, 1 for everything else.

#include <exception>
#include <iostream>
#include <map>
#include <new>

#include <dlfl/errors.h>
#include <dlfl/io/atomic_file.h>
#include "commands.h"
#include "feedback.h"
#include "file_checks.h"

int main(int argc, char** argv) {
  using namespace dlfl::tool;
  CLI::App app{"dlfl: topological modelling on the Doubly Linked Face List"};
  app.set_version_flag("--version", std::string("dlfl ") + DLFL_VERSION);
  app.require_subcommand(1);
  // Accepted before or after the subcommand ("dlfl -v subdivide ..." or "dlfl subdivide ... -v").
  app.fallthrough();
  app.add_flag("-v,--verbose", feedback().verbose, "Print a summary line per step and file (counts, time)");
  app.add_flag("-q,--quiet", feedback().quiet, "Print nothing but errors: no -v lines, no progress bar");
  // A stopped run leaves no temporary file: outputs are written beside their targets, then renamed.
  dlfl::remove_temporary_files_on_signals();
  std::map<const CLI::App*, Action> actions;
  auto add = [&](Action (*adder)(CLI::App&)) {
    Action a = adder(app);
    actions[app.get_subcommands({}).back()] = std::move(a);
  };
  add(add_info);
  add(add_check);
  add(add_convert);
  add(add_subdivide);
  add(add_replay);
  add(add_ops);
  add(add_edit);
  add(add_schemes);
  add(add_render);
  add(add_view);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return ok;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return ok;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return ok;
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return usage;
  }
  try {
    for (const CLI::App* sub : app.get_subcommands()) return actions.at(sub)();
  } catch (const dlfl::UnknownNameError& e) {
    // An unknown operation, scheme or parameter, or a malformed value: the command line is at fault.
    std::cerr << "error: " << e.what() << "\n";
    return usage;
  } catch (const UsageError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return usage;
  } catch (const dlfl::ParameterError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return usage;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory (the result is too large for this machine; try fewer iterations)\n";
    return failure;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return failure;
  }
  return usage;
}

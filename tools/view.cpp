// dlfl view IN -o OUT.html [-s SCHEME [-n N] [--param NAME=VALUE ...]] [--max-faces F]
// One self-contained HTML page that draws the mesh with WebGL, with a slider over M_0 ... M_N (a scheme's
// steps) or over the meshes after each op of an operation log given as IN. docs/viewer.md.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/cells/cell_io.h>
#include <dlfl/errors.h>
#include <dlfl/history/oplog.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/schemes/scheme_registry.h>
#include "commands.h"
#include "feedback.h"
#include "file_checks.h"
#include "scheme_options.h"
#include "viewer_page.h"

namespace dlfl::tool {

namespace {

// An operation log rather than a native JSON mesh: a .json document whose format is "dlfl-oplog". Returns
// its text then, empty otherwise.
std::string log_text_of(const std::string& path) {
  if (std::filesystem::path(path).extension() != ".json") return {};
  std::string text = io_detail::read_file(path);
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  const bool is_log = document.is_object() && document.value("format", "") == "dlfl-oplog";
  return is_log ? text : std::string();
}

// A step's label from the op the editor recorded last: its name, and what it applied or read.
std::string op_label(std::size_t index, const LoggedOperation& op) {
  std::string label = std::to_string(index) + ": " + op.name;
  if (op.name == "subdivide" && op.params.has("scheme")) label += " " + op.params.at("scheme").as_text();
  if (op.name == "load" && op.params.has("path"))
    label += " " + std::filesystem::path(op.params.at("path").as_text()).filename().string();
  return label;
}

// The meshes after each op of the log that can change the mesh (group brackets and clear_history cannot).
void add_log_steps(ViewerPage& page, const std::string& text, const std::string& name) {
  ReplayOptions options;
  options.after_op = [&](const Editor& editor, std::size_t op) {
    const LoggedOperation& logged = editor.log().back();
    if (logged.name == "begin_group" || logged.name == "end_group" || logged.name == "clear_history") return;
    page.add(editor.mesh(), op_label(op, logged));
  };
  const StepReport steps(0, 0);
  replay_log(text, name, options);
  if (page.steps() == 0) throw InvalidArgument(name + ": the log has no operation that makes a mesh");
}

// M_0 ... M_N: the input and the scheme's steps, each planned (from the scheme's closed-form counts) before
// it runs, so that a page too large is refused before the work.
void add_scheme_steps(ViewerPage& page, Mesh mesh, const SchemeOptions& scheme, const Params& params) {
  page.add(mesh, "M_0");
  std::optional<MeshCounts> counts = counts_of(mesh);
  std::size_t planned = 0;
  for (int i = 1; i <= scheme.iterations && counts; ++i) {
    counts = predict_counts(scheme.scheme, params, *counts, 1);
    if (counts) planned += static_cast<std::size_t>(counts->faces);
  }
  page.check_room(planned);
  const StepReport steps(scheme.iterations, static_cast<double>(planned));
  for (int i = 1; i <= scheme.iterations; ++i) {
    mesh = apply_scheme(mesh, scheme.scheme, params);
    page.add(mesh, "M_" + std::to_string(i));
  }
}

}  // namespace

Action add_view(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "view",
      "Write a self-contained HTML page that shows the mesh in a browser (WebGL), with a slider "
      "over a scheme's steps or a log's operations");
  struct Args : SchemeOptions {
    std::string in, out;
    std::size_t max_faces = 2'000'000;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("IN", a->in, "Input mesh (.obj, .off, .ply, .stl, .json) or operation log (.json)")
      ->required();
  cmd->add_option("-o,--output", a->out, "Output page (.html)")->required();
  const auto [scheme, iterations] = add_scheme_options(cmd, *a, false);
  iterations->needs(scheme);
  cmd->add_option("--max-faces", a->max_faces,
                  "Refuse a page whose steps hold more faces than this together (default 2000000)");
  return [a, scheme = scheme] {
    check_files({{"IN", a->in}}, {{"-o", a->out}});
    const std::string extension = std::filesystem::path(a->out).extension().string();
    if (extension != ".html" && extension != ".htm")
      throw UsageError("-o " + a->out + ": the page's name must end in .html or .htm");
    if (!a->params.empty() && !*scheme) throw UsageError("--param needs -s");
    if (is_cell_complex_file(a->in))
      throw InvalidArgument(a->in +
                            " is a cell complex; view draws DLFL meshes (.obj, .off, .ply, .stl, .json)");
    ViewerPage page(a->max_faces);
    const std::string log = log_text_of(a->in);
    if (!log.empty()) {
      if (*scheme) throw UsageError(a->in + " is an operation log: its ops are the steps, -s does not apply");
      add_log_steps(page, log, a->in);
    } else {
      // The scheme and its parameters are checked before the input is read: a typo costs nothing.
      const Params params = *scheme ? resolve_scheme_params(a->scheme, a->parsed_params()) : Params{};
      FileReport reading("read", a->in);
      Mesh mesh = read_mesh(a->in);
      reading.done(mesh);
      if (*scheme)
        add_scheme_steps(page, std::move(mesh), *a, params);
      else
        page.add(mesh, "M_0");
    }
    const std::string title =
        std::filesystem::path(a->in).filename().string() + (*scheme ? " (" + a->scheme + ")" : std::string());
    write_atomically(a->out, [&](std::ostream& out) { page.write(out, title); });
    say("write " + a->out + ": " + std::to_string(page.steps()) + " steps, " + std::to_string(page.faces()) +
        " faces");
    return ok;
  };
}

}  // namespace dlfl::tool

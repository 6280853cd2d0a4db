// dlfl subdivide IN -s SCHEME [-n ITER] [--param NAME=VALUE ...] -o OUT [--log LOG.json [--self-contained]]
// A cell-complex file (.vtk, or .obj with points or curves) takes the cell-complex path: -s mlca only.

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <dlfl/cells/cell_io.h>
#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/errors.h>
#include <dlfl/parameters.h>
#include <dlfl/schemes/scheme_registry.h>
#include "commands.h"
#include "editor_session.h"
#include "feedback.h"
#include "file_checks.h"
#include "scheme_options.h"

namespace dlfl::tool {

namespace {

// The memory a mesh of these counts takes in the kernel's arrays: per vertex a position and a corner, per
// corner (2 per edge) five handles, per edge two, per face a corner, a size and two flags.
double mesh_bytes(const MeshCounts& c) {
  return 28.0 * static_cast<double>(c.vertices) + (2 * 20.0 + 8.0) * static_cast<double>(c.edges) +
         12.0 * static_cast<double>(c.faces);
}

// What the machine can still give: MemAvailable of /proc/meminfo; 0 where it is unknown.
// DLFL_AVAILABLE_MEMORY (bytes) overrides it, to hold a run to less than the machine has.
double available_bytes() {
  if (const char* limit = std::getenv("DLFL_AVAILABLE_MEMORY")) return std::strtod(limit, nullptr);
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kib = 0;
  while (meminfo >> key >> kib) {
    if (key == "MemAvailable:") return kib * 1024.0;
    meminfo.ignore(256, '\n');
  }
  return 0;
}

// Plans a run from the scheme's closed forms, before the first step. Refuses a run whose result cannot fit
// in memory: the editor keeps the input, the last step reads the mesh before it while it builds the result,
// and writing it converts it once more, so the peak is taken as the input plus three times the result.
// Returns the faces of all the steps' results together, the progress bar's measure of the work (0 if the
// scheme declares no counts).
double plan_run(const Mesh& input, const std::string& scheme, const Params& params, int iterations) {
  const Params resolved = resolve_scheme_params(scheme, params);
  const MeshCounts start = counts_of(input);
  double faces = 0;
  std::optional<MeshCounts> predicted = start;
  for (int i = 1; i <= iterations && predicted; ++i) {
    predicted = predict_counts(scheme, resolved, *predicted, 1);
    if (predicted) faces += static_cast<double>(predicted->faces);
  }
  const double available = available_bytes();
  // Results beyond 32-bit handles are the subdivide operation's own refusal (a usage error, exit 2).
  if (!predicted || available == 0 || 2 * predicted->edges >= CornerId::invalid_index)
    return predicted ? faces : 0;
  const double needed = mesh_bytes(start) + 3 * mesh_bytes(*predicted);
  if (needed <= available) return faces;
  auto gib = [](double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", bytes / (1024.0 * 1024.0 * 1024.0));
    return std::string(text);
  };
  throw Error(std::to_string(iterations) + " steps of " + scheme + " would make " +
              std::to_string(predicted->faces) + " faces, needing about " + gib(needed) + " GiB where " +
              gib(available) + " GiB are available; try fewer iterations");
}

// MLCA on a cell complex (curves, quads, hexahedra, mixed as creases). Operation logs and the editor hold
// DLFL meshes, so they are refused here, before anything is read or written.
template <class Args>
Exit subdivide_cells(const Args& a) {
  if (a.scheme != "mlca") {
    throw InvalidArgument(a.files.in + " is a cell complex; only -s mlca subdivides cell complexes, not '" +
                          a.scheme + "'");
  }
  if (!a.params.empty()) throw InvalidArgument("mlca takes no parameters");
  if (!a.files.log.empty() || a.files.self_contained) {
    throw InvalidArgument("operation logs record DLFL meshes; --log is not available for a cell complex");
  }
  const CellComplex input = read_cell_complex(a.files.in);
  check_cell_complex_output(input, a.files.out);  // the output format, before the work (dimensions are kept)
  const CellComplex result = mlca_subdivide(input, a.iterations);
  CellWriteOptions write;
  write.binary_vtk = !a.files.ascii;
  write_cell_complex(result, a.files.out, write);
  return ok;
}

}  // namespace

Action add_subdivide(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("subdivide", "Apply a subdivision scheme, optionally recording an operation log");
  struct Args : SchemeOptions {
    EditorFiles files;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option(
         "IN", a->files.in,
         "Input mesh (.obj, .off, .ply, .stl, .json), or cell complex (.vtk, .obj with p or l lines) for "
         "-s mlca")
      ->required();
  add_scheme_options(cmd, *a, true);
  add_output_options(cmd, a->files, "Output mesh (format by extension)",
                     "Write PLY, STL or VTK as ASCII instead of binary");
  return [a] {
    check_editor_files(a->files);
    if (is_cell_complex_file(a->files.in)) return subdivide_cells(*a);
    const Params params = a->parsed_params();
    Editor editor = open_editor(a->files);
    const double predicted_faces = plan_run(editor.mesh(), a->scheme, params, a->iterations);
    {
      StepReport report(a->iterations, predicted_faces);
      editor.subdivide(a->scheme, params, a->iterations);
    }
    save_editor(editor, a->files);
    return ok;
  };
}

}  // namespace dlfl::tool

// dlfl render IN -o OUT.png|OUT.svg: a picture of a mesh or cell complex; with -s SCHEME -n N a contact sheet
// of M_0 ... M_N, and with LOG.json --steps one of the mesh after each logged operation.

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <string>
#include <system_error>
#include <tuple>
#include <vector>

#include <dlfl/cells/cell_io.h>
#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/errors.h>
#include <dlfl/history/oplog.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/parameters.h>
#include <dlfl/render/contact_sheet.h>
#include <dlfl/render/picture_settings.h>
#include <dlfl/render/png.h>
#include <dlfl/render/rasterizer.h>
#include <dlfl/schemes/scheme_registry.h>
#include "commands.h"
#include "feedback.h"
#include "file_checks.h"

namespace dlfl::tool {

namespace {

struct RenderArgs {
  std::string in, out, size = "800x600", view = "iso", color_by = "face-size", background = "white", scheme;
  double azimuth = 0, elevation = 0, zoom = 1;
  bool fit = false, edges = true, transparent = false, smooth = false, steps = false;
  int iterations = 1;
  std::vector<std::string> params;
  CLI::Option *azimuth_option, *elevation_option, *edges_option;
};

// "WxH"; the sizes themselves are checked by picture_setup.
std::pair<std::int64_t, std::int64_t> parse_size(const std::string& text) {
  const auto whole = [](const char* first, const char* last, std::int64_t& value) {
    const auto [end, error] = std::from_chars(first, last, value);
    return first < last && end == last && error == std::errc();
  };
  const std::size_t x = text.find('x');
  std::int64_t w = 0, h = 0;
  const char* start = text.data();
  if (x == std::string::npos || !whole(start, start + x, w) || !whole(start + x + 1, start + text.size(), h))
    throw UsageError("--size: expected WxH (two whole numbers of pixels), got '" + text + "'");
  return {w, h};
}

std::string mesh_counts(const Mesh& mesh) {
  return "V " + std::to_string(mesh.num_vertices()) + " E " + std::to_string(mesh.num_edges()) + " F " +
         std::to_string(mesh.num_surface_faces());
}

struct Frames {
  std::vector<RenderScene> scenes;
  std::vector<std::string> captions;
};

// The mesh after each logged operation (an undo entry: a group is one), from the first load on.
Frames log_steps(const RenderArgs& a, const ColorBy& color_by) {
  Editor editor = replay_log_file(a.in);
  const auto history = editor.undo_history();
  std::vector<Mesh> meshes{editor.mesh()};
  while (editor.undo()) meshes.push_back(editor.mesh());
  std::reverse(meshes.begin(), meshes.end());
  Frames frames;
  // meshes[k] is the mesh after entry k - 1 (meshes[0], before the first kept entry, is shown when the undo
  // limit dropped the entries before it; the empty mesh before a log's first load is not).
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    if (meshes[k].empty()) continue;
    const std::string name = k == 0 ? "start" : history[k - 1].label;
    frames.scenes.push_back(mesh_scene(meshes[k], color_by));
    frames.captions.push_back(std::to_string(frames.captions.size()) + " " + name + "\n" +
                              mesh_counts(meshes[k]));
  }
  if (frames.scenes.empty()) throw Error(a.in + ": the log holds no mesh to draw");
  return frames;
}

Frames cell_frames(const RenderArgs& a, const ColorBy& color_by) {
  if (!a.scheme.empty() && a.scheme != "mlca") {
    throw UsageError(a.in + " is a cell complex; only -s mlca subdivides cell complexes, not '" + a.scheme +
                     "'");
  }
  if (!a.params.empty()) throw UsageError("mlca takes no parameters");
  CellComplex complex = read_cell_complex(a.in);
  Frames frames;
  const int last = a.scheme.empty() ? 0 : a.iterations;
  for (int n = 0; n <= last; ++n) {
    if (n > 0) complex = mlca_subdivide(complex, 1);
    frames.scenes.push_back(cell_scene(complex, color_by));
    frames.captions.push_back("M" + std::to_string(n) + "\nV " + std::to_string(complex.positions.size()) +
                              " C " + std::to_string(complex.num_cells()));
  }
  return frames;
}

Frames mesh_frames(const RenderArgs& a, const ColorBy& color_by) {
  Params params;
  for (const auto& p : a.params) {
    auto [name, value] = parse_assignment(p);
    if (params.has(name)) throw ParameterError("parameter " + name + " given twice", name);
    params[name] = std::move(value);
  }
  if (!a.scheme.empty()) params = resolve_scheme_params(a.scheme, params);  // before any work
  FileReport reading("read", a.in);
  Mesh mesh = read_mesh(a.in);
  reading.done(mesh);
  Frames frames;
  const int last = a.scheme.empty() ? 0 : a.iterations;
  for (int n = 0; n <= last; ++n) {
    if (n > 0) {
      StepReport report(1, 0);
      mesh = apply_scheme(mesh, a.scheme, params);
    }
    frames.scenes.push_back(mesh_scene(mesh, color_by));
    frames.captions.push_back("M" + std::to_string(n) + "\n" + mesh_counts(mesh));
  }
  return frames;
}

Exit run_render(const RenderArgs& a) {
  check_files({{"IN", a.in}}, {{"-o", a.out}});
  const std::optional<PictureFormat> format = picture_format(a.out);
  if (!format) throw UsageError("-o: the picture is written as .png or .svg, not '" + a.out + "'");
  const bool sheet = !a.scheme.empty() || a.steps;
  if (sheet && format == PictureFormat::svg)
    throw UsageError("-o: a contact sheet (-s or --steps) is written as .png");
  if (a.steps && !a.scheme.empty()) throw UsageError("--steps draws a log's operations; it takes no -s");
  PictureSettings settings;
  std::tie(settings.width, settings.height) = parse_size(a.size);
  settings.view = a.view;
  if (a.azimuth_option->count() > 0) settings.azimuth = a.azimuth;
  if (a.elevation_option->count() > 0) settings.elevation = a.elevation;
  settings.zoom = a.zoom;
  if (a.edges_option->count() > 0) settings.edges = a.edges;
  settings.smooth = a.smooth;
  settings.color_by = a.color_by;
  settings.background = a.background;
  settings.transparent = a.transparent;
  const PictureSetup setup = picture_setup(settings);
  const ColorBy& color_by = setup.color_by;
  const RenderOptions& options = setup.options;

  const Frames frames = a.steps                      ? log_steps(a, color_by)
                        : is_cell_complex_file(a.in) ? cell_frames(a, color_by)
                                                     : mesh_frames(a, color_by);
  if (!sheet) {
    write_picture(frames.scenes[0], fitted_camera(setup, frames.scenes), options, a.out);
    return ok;
  }
  const Camera camera = fitted_camera(setup, frames.scenes);
  std::vector<Image> pictures;
  for (const RenderScene& scene : frames.scenes) pictures.push_back(render(scene, camera, options));
  Rgba text =
      options.background.a == 0 || options.background.r + options.background.g + options.background.b > 384
          ? Rgba{30, 30, 30, 255}
          : Rgba{235, 235, 235, 255};
  write_png(contact_sheet(pictures, frames.captions, options.background, text), a.out);
  return ok;
}

}  // namespace

Action add_render(CLI::App& app) {
  auto* cmd = app.add_subcommand("render",
                                 "Draw a mesh or cell complex as PNG or SVG; -s SCHEME -n N or a log with "
                                 "--steps draws a contact sheet");
  auto a = std::make_shared<RenderArgs>();
  cmd->add_option("IN", a->in,
                  "Mesh (.obj, .off, .ply, .stl, .json), cell complex (.vtk, .obj with p or l), or "
                  "operation log (.json) with --steps")
      ->required();
  cmd->add_option("-o,--output", a->out, "Picture: .png, or .svg (a vector drawing)")->required();
  cmd->add_option("--size", a->size, "Picture size WxH in pixels (default 800x600; each picture of a sheet)");
  cmd->add_option("--view", a->view, "front, back, left, right, top, bottom or iso (default iso)");
  a->azimuth_option =
      cmd->add_option("--azimuth", a->azimuth, "Degrees around the y axis (0: front, 90: right)");
  a->elevation_option = cmd->add_option("--elevation", a->elevation, "Degrees above the xz plane (90: top)");
  auto* fit = cmd->add_flag("--fit", a->fit, "Fit the whole model in the picture (the default)");
  cmd->add_option("--zoom", a->zoom, "Magnify the fitted picture around its centre (default 1)")
      ->excludes(fit);
  a->edges_option =
      cmd->add_flag("--edges,!--no-edges", a->edges, "Draw the edges (default: on below 200000 faces)");
  cmd->add_option("--color-by", a->color_by,
                  "none, face-size (default), component, hole, concave (faces beside a concave edge), or "
                  "attribute=NAME (a number or boolean on faces "
                  "or vertices)");
  cmd->add_option("--background", a->background,
                  "Background colour: #RRGGBB or white, black, gray (default white)");
  cmd->add_flag("--transparent", a->transparent, "Transparent background");
  cmd->add_flag("--smooth", a->smooth, "Smooth shading (vertex normals) instead of flat faces");
  std::string names;
  for (const auto& n : scheme_names()) names += (names.empty() ? "" : ", ") + n;
  auto* scheme =
      cmd->add_option("-s,--scheme", a->scheme, "Contact sheet of M_0 ... M_N of a scheme: " + names);
  cmd->add_option("-n,--iterations", a->iterations, "N, the steps of the sheet (default 1)")
      ->check(CLI::Range(0, 12))
      ->needs(scheme);
  cmd->add_option("--param", a->params, "Scheme parameter NAME=VALUE (repeatable)")->needs(scheme);
  cmd->add_flag("--steps", a->steps,
                "IN is an operation log: a contact sheet of the mesh after each operation");
  return [a] { return run_render(*a); };
}

}  // namespace dlfl::tool

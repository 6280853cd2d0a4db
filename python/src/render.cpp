// Pictures: dlfl.render draws a mesh or a cell complex with the library's renderer (dlfl/render/), as a
// NumPy RGBA array or as a PNG or SVG file, with the settings of `dlfl render` (docs/rendering.md). The GIL
// is released while the picture is drawn and written.

#include <pybind11/stl.h>

#include <climits>
#include <optional>
#include <span>
#include <tuple>

#include <dlfl/render/picture_settings.h>
#include <dlfl/render/rasterizer.h>
#include "binding.h"

namespace dlfl::python {
namespace {

// One side of `size`: an integer (NumPy integers too); one too large for 64 bits is kept as the largest,
// which picture_setup refuses with the others.
std::int64_t size_side(py::handle side, py::handle size) {
  if (!PyIndex_Check(side.ptr()) || PyBool_Check(side.ptr())) {
    throw ParameterError("size: expected (width, height), two integers, got " + std::string(py::repr(size)),
                         "size");
  }
  const auto index = py::reinterpret_steal<py::object>(PyNumber_Index(side.ptr()));
  if (!index) throw py::error_already_set();
  int overflow = 0;
  const long long value = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  return overflow > 0 ? LLONG_MAX : overflow < 0 ? LLONG_MIN : value;
}

std::pair<std::int64_t, std::int64_t> picture_size(py::handle size) {
  if (!PySequence_Check(size.ptr()) || py::isinstance<py::str>(size) || py::len(size) != 2) {
    throw ParameterError("size: expected (width, height), two integers, got " + std::string(py::repr(size)),
                         "size");
  }
  const auto sides = py::reinterpret_borrow<py::sequence>(size);
  return {size_side(sides[0], size), size_side(sides[1], size)};
}

// The picture as an (height, width, 4) uint8 array over the image's own storage, which the array keeps.
py::array image_array(Image image) {
  static_assert(sizeof(Rgba) == 4, "a pixel is four packed bytes");
  const py::ssize_t width = image.width(), height = image.height();
  auto* keep = new Image(std::move(image));
  const py::capsule owner(keep, [](void* p) { delete static_cast<Image*>(p); });
  return py::array(py::dtype::of<std::uint8_t>(), {height, width, py::ssize_t(4)},
                   {4 * width, py::ssize_t(4), py::ssize_t(1)}, &keep->at(0, 0).r, owner);
}

// The picture of `scene` written to `path`, or else drawn into an image. Touches no Python object: it runs
// without the GIL.
std::optional<Image> draw(const RenderScene& scene, const PictureSetup& setup,
                          const std::optional<std::string>& path) {
  const Camera camera = fitted_camera(setup, std::span(&scene, 1));
  if (!path) return render(scene, camera, setup.options);
  write_picture(scene, camera, setup.options, *path);
  return std::nullopt;
}

py::object render_picture(const py::object& object, const py::object& path, const py::object& size,
                          const std::string& view, std::optional<double> azimuth,
                          std::optional<double> elevation, double zoom, std::optional<bool> edges,
                          bool smooth, const std::string& color_by, const std::string& background,
                          bool transparent) {
  PictureSettings settings;
  std::tie(settings.width, settings.height) = picture_size(size);
  settings.view = view;
  settings.azimuth = azimuth;
  settings.elevation = elevation;
  settings.zoom = zoom;
  settings.edges = edges;
  settings.smooth = smooth;
  settings.color_by = color_by;
  settings.background = background;
  settings.transparent = transparent;
  const PictureSetup setup = picture_setup(settings);
  std::optional<std::string> file;
  if (!path.is_none()) {
    file = path_text(path);
    if (!picture_format(*file)) {
      throw InvalidArgument("render: '" + *file + "': a picture is written as .png or .svg");
    }
  }
  std::optional<Image> image;
  if (py::isinstance<MeshRef>(object)) {
    image = object.cast<const MeshRef&>().read_without_gil(
        [&](const Mesh& mesh) { return draw(mesh_scene(mesh, setup.color_by), setup, file); });
  } else if (py::isinstance<ComplexRef>(object)) {
    const CellComplex& complex = *object.cast<const ComplexRef&>().complex;
    py::gil_scoped_release no_gil;
    image = draw(cell_scene(complex, setup.color_by), setup, file);
  } else {
    throw py::type_error("render: expected a dlfl.Mesh or a dlfl.CellComplex, got " +
                         std::string(py::str(py::type::of(object).attr("__name__"))));
  }
  return image ? py::object(image_array(std::move(*image))) : py::object(py::none());
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render", &render_picture,
        R"doc(Draws a Mesh (an editor's live mesh too) or a CellComplex with the library's software renderer,
as `dlfl render` does (docs/rendering.md), with the same settings, defaults and refusals:

    size         (width, height) in pixels, each from 1 to 16384, at most 2^26 pixels in all
    view         "front" (from +z), "back", "left", "right" (from +x), "top" (from +y), "bottom", "iso"
    azimuth, elevation
                 degrees, replacing the view's: the camera sits in the direction
                 (cos E sin A, sin E, cos E cos A); models are taken as y-up
    zoom         times the fitted scale (the whole model with a 5% margin), 0 < zoom <= 1000
    edges        draw the edges; None: on below 200,000 faces
    smooth       interpolated vertex normals instead of flat faces
    color_by     "none", "face-size", "component", "hole" or "attribute=NAME" (cell complexes: "none" or
                 "face-size")
    background   "#RRGGBB", "#RRGGBBAA", "white", "black", "gray"
    transparent  a transparent background

Without `path`, returns the picture as a NumPy uint8 array of shape (height, width, 4): RGBA, row 0 the
top. With `path` (.png or .svg, by its extension), writes the file atomically and returns None. Every
setting is checked before anything is drawn or written: a bad one raises ParameterError naming it ("size",
"view", "azimuth", "elevation", "zoom", "color_by", "background"), and any other extension InvalidArgument
naming the path; no file is written then. The orthographic camera's fit is
    scale = zoom * min(0.9 width / extent_right, 0.9 height / extent_up)
pixels per unit, so sizes in the picture can be predicted. The GIL is released while drawing.)doc",
        py::arg("obj"), py::arg("path") = py::none(), py::kw_only(),
        py::arg("size") = py::make_tuple(800, 600), py::arg("view") = "iso", py::arg("azimuth") = py::none(),
        py::arg("elevation") = py::none(), py::arg("zoom") = 1.0, py::arg("edges") = py::none(),
        py::arg("smooth") = false, py::arg("color_by") = "face-size", py::arg("background") = "white",
        py::arg("transparent") = false);
}

}  // namespace dlfl::python

#include <dlfl/render/picture_settings.h>

#include <algorithm>
#include <cctype>

#include <dlfl/errors.h>
#include <dlfl/render/png.h>
#include <dlfl/render/rasterizer.h>
#include <dlfl/render/svg.h>

namespace dlfl {

PictureSetup picture_setup(const PictureSettings& s) {
  const auto side_ok = [](std::int64_t side) { return side >= 1 && side <= max_picture_side; };
  if (!side_ok(s.width) || !side_ok(s.height) || s.width * s.height > max_picture_pixels) {
    throw ParameterError(
        "size: width and height must be from 1 to 16384 and at most 2^26 pixels in all, got " +
            std::to_string(s.width) + "x" + std::to_string(s.height),
        "size");
  }
  ViewAngles angles = view_angles(parse_view(s.view));
  if (s.azimuth) angles.azimuth = *s.azimuth;
  if (s.elevation) angles.elevation = *s.elevation;
  Camera camera(angles, int(s.width), int(s.height));
  // Checked here as well as by Camera::fit, so that a bad zoom is refused before anything is read or drawn.
  if (!(s.zoom > 0 && s.zoom <= 1000)) throw ParameterError("zoom: must be above 0 and at most 1000", "zoom");
  const ColorBy color_by = parse_color_by(s.color_by);
  RenderOptions options;
  options.background = parse_color(s.background, "background");
  if (s.transparent) options.background.a = 0;
  options.smooth = s.smooth;
  options.edges = s.edges;
  return {camera, s.zoom, color_by, options};
}

Camera fitted_camera(const PictureSetup& setup, std::span<const RenderScene> scenes) {
  Camera camera = setup.camera;
  for (const RenderScene& scene : scenes) camera.include(scene.positions);
  camera.fit(setup.zoom);
  return camera;
}

std::optional<PictureFormat> picture_format(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return PictureFormat::png;
  if (ext == ".svg") return PictureFormat::svg;
  return std::nullopt;
}

void write_picture(const RenderScene& scene, const Camera& camera, const RenderOptions& options,
                   const std::filesystem::path& path, FileBatch* batch) {
  const std::optional<PictureFormat> format = picture_format(path);
  if (!format) {
    throw InvalidArgument("'" + path.string() + "': a picture is written as .png or .svg");
  }
  if (*format == PictureFormat::svg) {
    write_svg(scene, camera, options, path, batch);
  } else {
    write_png(render(scene, camera, options), path, batch);
  }
}

}  // namespace dlfl

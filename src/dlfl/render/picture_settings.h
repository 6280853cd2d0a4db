#pragma once
// The settings of one picture as a user gives them (the flags of `dlfl render`, the keywords of
// dlfl.render), checked and turned into a camera, a colouring and drawing options: one reading for the tool
// and the Python binding, so that both accept, refuse and draw alike.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include <dlfl/render/camera.h>
#include <dlfl/render/colors.h>
#include <dlfl/render/scene.h>
#include <dlfl/render/shading.h>

namespace dlfl {

class FileBatch;

/// The largest picture side, and the most pixels in all (the rasterizer takes 32 bytes a pixel).
inline constexpr std::int64_t max_picture_side = 16384;
inline constexpr std::int64_t max_picture_pixels = std::int64_t(1) << 26;

/// One picture's settings, with the defaults of `dlfl render` (docs/rendering.md).
struct PictureSettings {
  std::int64_t width = 800, height = 600;
  std::string view = "iso";            ///< front, back, left, right, top, bottom, iso
  std::optional<double> azimuth;       ///< degrees; replaces the view's azimuth
  std::optional<double> elevation;     ///< degrees; replaces the view's elevation
  double zoom = 1;                     ///< times the fitted scale, 0 < zoom <= 1000
  std::optional<bool> edges;           ///< unset: on below `edges_by_default_below` polygons
  bool smooth = false;                 ///< vertex normals instead of flat faces
  std::string color_by = "face-size";  ///< as `parse_color_by` reads it
  std::string background = "white";    ///< as `parse_color` reads it
  bool transparent = false;            ///< the background's alpha 0
};

/// The settings read: a camera to be fitted to what it shows (`Camera::include`, then `fit(zoom)`), the
/// colouring of the faces and the drawing options.
struct PictureSetup {
  Camera camera;
  double zoom;
  ColorBy color_by;
  RenderOptions options;
};

/// Reads and checks every setting before anything is drawn. Throws ParameterError naming "size" (a side
/// outside 1 to `max_picture_side`, or more than `max_picture_pixels`), "view", "azimuth", "elevation"
/// (not finite), "zoom", "color_by" or "background".
PictureSetup picture_setup(const PictureSettings& settings);

/// The setup's camera fitted to all of `scenes` (one for a single picture; the pictures of a contact sheet
/// share one camera, so that sizes compare across the sheet). O(positions).
Camera fitted_camera(const PictureSetup& setup, std::span<const RenderScene> scenes);

enum class PictureFormat { png, svg };

/// The format of a picture file by its extension, in either case (.png, .svg); nullopt for any other.
std::optional<PictureFormat> picture_format(const std::filesystem::path& path);

/// Writes one picture of `scene` to `path` atomically (or staged in `batch`), PNG or SVG by the extension
/// (write_png, write_svg). Throws InvalidArgument naming the path for another extension, before any file is
/// touched; IoError naming the path when writing fails.
void write_picture(const RenderScene& scene, const Camera& camera, const RenderOptions& options,
                   const std::filesystem::path& path, FileBatch* batch = nullptr);

}  // namespace dlfl

#pragma once
// How a picture is drawn (RenderOptions) and how a face is lit and tinted: one definition for the rasterizer
// and the SVG writer, so that both show the same colours.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include <glm/vec3.hpp>

#include <dlfl/render/colors.h>
#include <dlfl/render/image.h>
#include <dlfl/render/scene.h>

namespace dlfl {

/// Edges are drawn by default on scenes of fewer polygons than this; above, they would cover the faces.
inline constexpr std::size_t edges_by_default_below = 200000;

struct RenderOptions {
  std::optional<bool> edges;  ///< draw the edges; unset: on below `edges_by_default_below` polygons
  bool smooth = false;        ///< interpolate vertex normals (oriented scenes only) instead of flat faces
  bool back_tint = true;      ///< faces seen from behind are mixed with `back_color` (oriented scenes only)
  Rgba background{255, 255, 255, 255};  ///< alpha 0 for a transparent picture

  bool draws_edges(const RenderScene& scene) const {
    return edges.value_or(scene.num_polygons() < edges_by_default_below);
  }
};

/// The light: a direction in camera coordinates (x right, y up, z towards the viewer), from the upper left
/// in front, and the share of ambient light. A face turned to the viewer is lit at
/// light_ambient + (1 - light_ambient) * cos(angle to the light).
inline constexpr double light_ambient = 0.35;
inline const glm::dvec3 light_direction = glm::dvec3(-0.3, 0.4, 1.0) / std::sqrt(0.3 * 0.3 + 0.4 * 0.4 + 1.0);

/// The brightness of a surface of camera-space normal `n` (any length, either side: lit two-sided, the
/// normal turned towards the viewer), in [light_ambient, 1].
inline double light_intensity(const glm::dvec3& n) {
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  if (!(length > 0)) return light_ambient;
  const double cosine =
      (n.x * light_direction.x + n.y * light_direction.y + n.z * light_direction.z) / length;
  return light_ambient + (1 - light_ambient) * std::max(0.0, n.z < 0 ? -cosine : cosine);
}

/// The fill colour of a face seen from behind: 60% `back_color`, 40% its own.
inline Rgba back_tinted(Rgba c) {
  auto channel = [](std::uint8_t own, std::uint8_t back) {
    return static_cast<std::uint8_t>((2 * own + 3 * back + 2) / 5);
  };
  return {channel(c.r, back_color.r), channel(c.g, back_color.g), channel(c.b, back_color.b), 255};
}

/// `c` scaled by `intensity` (in [0, 1]), rounded.
inline Rgba lit(Rgba c, double intensity) {
  auto channel = [intensity](std::uint8_t x) {
    return static_cast<std::uint8_t>(std::lround(x * intensity));
  };
  return {channel(c.r), channel(c.g), channel(c.b), c.a};
}

}  // namespace dlfl

#pragma once
// Where a picture is taken from: an orthographic camera looking at the model from a named view or from an
// azimuth and elevation, fitted to what it shows.
//
// Orthographic, not perspective: parallel edges stay parallel and sizes do not depend on depth, which is
// what a picture of a model for a paper wants; the fit is exact (the model's projected extent, no near plane
// to clip against); and the size of a projected face follows from one scale factor, so tests can predict
// pixels by hand.

#include <span>
#include <string_view>

#include <glm/vec3.hpp>

namespace dlfl {

/// The named views. Models are taken as y-up: `front` looks from +z towards -z, `right` from +x, `top` from
/// +y (with -z up in the picture), `iso` from the direction (1, 1, 1).
enum class View { front, back, left, right, top, bottom, iso };

/// The view of that name ("front", "back", "left", "right", "top", "bottom", "iso"). Throws ParameterError
/// naming "view" for any other.
View parse_view(std::string_view name);

/// Degrees. The camera sits in the direction (cos(el) sin(az), sin(el), cos(el) cos(az)) from the model:
/// azimuth 0 and elevation 0 is the front view, azimuth 90 the right view, elevation 90 the top view.
struct ViewAngles {
  double azimuth = 0;
  double elevation = 0;
};

/// front (0, 0), back (180, 0), left (-90, 0), right (90, 0), top (0, 90), bottom (0, -90), iso (45,
/// atan(1/sqrt 2) = 35.26...).
ViewAngles view_angles(View view);

/// An orthographic camera. A point p goes to the picture point
///   x = width / 2 + scale * dot(p - center, right),  y = height / 2 - scale * dot(p - center, up)
/// (pixels, y down; pixel (i, j) covers [i, i+1) x [j, j+1)), and its nearness to the viewer is
/// dot(p - center, toward), larger being nearer.
///
/// `fit` chooses `center` and `scale` so that every point the camera was shown (`include`) is in the
/// picture with a margin of `fit_margin` of the width and height on each side:
///   scale = zoom * min(width (1 - 2 margin) / extent_right, height (1 - 2 margin) / extent_up),
/// with `center` the middle of the points' extent along `right` and `up` (an extent of zero is left out of
/// the minimum; with both zero, scale is zoom times the smaller of the width and height).
class Camera {
 public:
  static constexpr double fit_margin = 0.05;

  /// Throws ParameterError for a non-finite angle ("azimuth", "elevation") or a size below 1 ("size").
  Camera(ViewAngles angles, int width, int height);

  /// Widens the extent to be fitted to these points. O(points).
  void include(std::span<const glm::dvec3> points);
  /// Sets `center` and `scale` from the extent seen so far (see the class comment). Throws ParameterError
  /// naming "zoom" unless 0 < zoom <= 1000.
  void fit(double zoom = 1);

  /// The picture point (x, y) and nearness (z) of p.
  glm::dvec3 project(const glm::dvec3& p) const {
    const glm::dvec3 d = p - center;
    return {0.5 * width + scale * dot(d, right), 0.5 * height - scale * dot(d, up), dot(d, toward)};
  }
  /// Camera coordinates of a direction: (along right, along up, along toward).
  glm::dvec3 to_view(const glm::dvec3& direction) const {
    return {dot(direction, right), dot(direction, up), dot(direction, toward)};
  }

  glm::dvec3 right, up, toward;  ///< orthonormal; toward points from the model to the viewer
  glm::dvec3 center{0.0};
  double scale = 1;  ///< pixels per model unit
  int width, height;

 private:
  static double dot(const glm::dvec3& a, const glm::dvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
  glm::dvec3 low_, high_;  // extent along (right, up, toward)
  bool empty_ = true;
};

}  // namespace dlfl

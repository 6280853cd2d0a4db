#include <dlfl/render/camera.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <dlfl/errors.h>

namespace dlfl {

namespace {

constexpr std::string_view view_names[] = {"front", "back", "left", "right", "top", "bottom", "iso"};

}  // namespace

View parse_view(std::string_view name) {
  for (std::size_t i = 0; i < std::size(view_names); ++i) {
    if (name == view_names[i]) return static_cast<View>(i);
  }
  throw ParameterError(
      "view: expected front, back, left, right, top, bottom or iso, got '" + std::string(name) + "'", "view");
}

ViewAngles view_angles(View view) {
  switch (view) {
    case View::front:
      return {0, 0};
    case View::back:
      return {180, 0};
    case View::left:
      return {-90, 0};
    case View::right:
      return {90, 0};
    case View::top:
      return {0, 90};
    case View::bottom:
      return {0, -90};
    case View::iso:
      break;
  }
  return {45, std::atan(1 / std::sqrt(2.0)) * 180 / std::numbers::pi};
}

Camera::Camera(ViewAngles angles, int width, int height) : width(width), height(height) {
  if (!std::isfinite(angles.azimuth))
    throw ParameterError("azimuth: not a finite number of degrees", "azimuth");
  if (!std::isfinite(angles.elevation)) {
    throw ParameterError("elevation: not a finite number of degrees", "elevation");
  }
  if (width < 1 || height < 1) throw ParameterError("size: width and height must be at least 1", "size");
  const double az = angles.azimuth * std::numbers::pi / 180, el = angles.elevation * std::numbers::pi / 180;
  toward = {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
  // cross(y, toward) normalised, written out so that it stays defined looking straight down or up.
  right = {std::cos(az), 0, -std::sin(az)};
  up = {toward.y * right.z - toward.z * right.y, toward.z * right.x - toward.x * right.z,
        toward.x * right.y - toward.y * right.x};
}

void Camera::include(std::span<const glm::dvec3> points) {
  for (const glm::dvec3& p : points) {
    const glm::dvec3 q = to_view(p);
    if (empty_) {
      low_ = high_ = q;
      empty_ = false;
    }
    low_ = glm::dvec3(std::min(low_.x, q.x), std::min(low_.y, q.y), std::min(low_.z, q.z));
    high_ = glm::dvec3(std::max(high_.x, q.x), std::max(high_.y, q.y), std::max(high_.z, q.z));
  }
}

void Camera::fit(double zoom) {
  if (!(zoom > 0 && zoom <= 1000)) throw ParameterError("zoom: must be above 0 and at most 1000", "zoom");
  if (empty_) {
    center = glm::dvec3(0.0);
    scale = zoom * std::min(width, height);
    return;
  }
  const glm::dvec3 mid = 0.5 * (low_ + high_);
  center = mid.x * right + mid.y * up + mid.z * toward;
  const double usable = 1 - 2 * fit_margin;
  const double extent_x = high_.x - low_.x, extent_y = high_.y - low_.y;
  double fitted = std::numeric_limits<double>::infinity();
  if (extent_x > 0) fitted = std::min(fitted, width * usable / extent_x);
  if (extent_y > 0) fitted = std::min(fitted, height * usable / extent_y);
  if (!std::isfinite(fitted)) fitted = std::min(width, height);
  scale = zoom * fitted;
}

}  // namespace dlfl

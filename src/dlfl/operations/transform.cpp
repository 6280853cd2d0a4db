// transform: see transform.h.

#include <dlfl/operations/transform.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

[[noreturn]] void refuse(const char* parameter, const std::string& what) {
  throw ParameterError(std::string("transform: parameter ") + parameter + " " + what, parameter);
}

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

glm::dvec3 bounding_box_center(const Mesh& m) {
  if (m.empty()) return glm::dvec3(0.0);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (VertexId v : m.vertices()) {
    lo = glm::min(lo, m.position(v));
    hi = glm::max(hi, m.position(v));
  }
  // Half of each, then the sum: no overflow for boxes near the largest doubles.
  return 0.5 * lo + 0.5 * hi;
}

// The axis scaled to unit length; scaled by its largest component first, so that a tiny or huge axis keeps
// its direction. Zero for a zero axis.
glm::dvec3 unit_axis(const glm::dvec3& axis) {
  const double largest = std::max({std::abs(axis.x), std::abs(axis.y), std::abs(axis.z)});
  return largest > 0.0 ? glm::normalize(axis / largest) : glm::dvec3(0.0);
}

// The map as applied to each vertex: the displacement from the centre scaled and rotated (Rodrigues'
// formula about the unit axis k).
class AffineMap {
 public:
  AffineMap(const Mesh& m, const TransformOptions& o)
      : center_(o.center ? *o.center : bounding_box_center(m)),
        scale_(o.scale),
        translate_(o.translate),
        axis_(unit_axis(o.rotate_axis)),
        rotates_(o.rotate_degrees != 0.0) {
    const double radians = o.rotate_degrees * (std::numbers::pi / 180.0);
    cos_ = std::cos(radians);
    sin_ = std::sin(radians);
  }

  // Where p goes before the translation is added, as p plus a displacement, so that a map that changes
  // nothing gives back p bit for bit.
  glm::dvec3 untranslated(const glm::dvec3& p) const {
    const glm::dvec3 d = p - center_;
    glm::dvec3 moved = scale_ * d;
    if (rotates_) {
      moved =
          moved * cos_ + glm::cross(axis_, moved) * sin_ + axis_ * (glm::dot(axis_, moved) * (1.0 - cos_));
    }
    return p + (moved - d);
  }
  glm::dvec3 operator()(const glm::dvec3& p) const { return untranslated(p) + translate_; }

 private:
  glm::dvec3 center_, scale_, translate_, axis_;
  bool rotates_;
  double cos_ = 1.0, sin_ = 0.0;
};

TransformOptions options_of(const Params& p) {
  TransformOptions o;
  o.translate = p.point("translate");
  o.scale = p.point("scale");
  o.rotate_axis = p.point("rotate_axis");
  o.rotate_degrees = p.number("rotate_degrees");
  if (p.has("center")) o.center = p.point("center");
  return o;
}

}  // namespace

void check_transform(const Mesh& m, const TransformOptions& o) {
  if (!finite(o.translate)) refuse("translate", "is not finite");
  if (!finite(o.scale)) refuse("scale", "is not finite");
  if (!finite(o.rotate_axis)) refuse("rotate_axis", "is not finite");
  if (!std::isfinite(o.rotate_degrees)) refuse("rotate_degrees", "is not finite");
  if (o.center && !finite(*o.center)) refuse("center", "is not finite");
  if (o.rotate_axis == glm::dvec3(0.0)) refuse("rotate_axis", "is zero: it gives no direction to turn about");
  const glm::dvec3& s = o.scale;
  if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0) {
    refuse("scale", "= " + format_number(s.x) + "," + format_number(s.y) + "," + format_number(s.z) +
                        " has a zero component, which would flatten the mesh");
  }
  if ((s.x < 0.0) != ((s.y < 0.0) != (s.z < 0.0))) {
    refuse("scale", "= " + format_number(s.x) + "," + format_number(s.y) + "," + format_number(s.z) +
                        " has an odd number of negative components: a mirror, which would turn the faces "
                        "inside out (use reverse_orientation for that)");
  }
  const AffineMap map(m, o);
  for (VertexId v : m.vertices()) {
    if (!finite(map.untranslated(m.position(v))))
      refuse("scale", "would move a vertex to a non-finite position");
    if (!finite(map(m.position(v)))) refuse("translate", "would move a vertex to a non-finite position");
  }
}

void transform(Transaction& tx, const TransformOptions& options) {
  check_transform(tx.mesh(), options);
  const AffineMap map(tx.mesh(), options);
  // The positions first: a vertex written early would move the bounding box the others are mapped about.
  std::vector<std::pair<VertexId, glm::dvec3>> moves;
  for (VertexId v : tx.mesh().vertices()) {
    const glm::dvec3 to = map(tx.mesh().position(v));
    if (to != tx.mesh().position(v)) moves.emplace_back(v, to);
  }
  for (const auto& [v, to] : moves) tx.set_position(v, to);
}

std::vector<OperationSpec> detail::transform_operation_specs() {
  return {edit_operation(
      "transform",
      "moves every vertex: scale per axis and rotate about a centre, then translate: p' = center + "
      "R(scale * (p - center)) + translate",
      {param("translate", ParamType::point, glm::dvec3(0.0), "added last"),
       param("scale", ParamType::point, glm::dvec3(1.0),
             "per axis, about the centre; no zero component, an even number of negative ones"),
       param("rotate_axis", ParamType::point, glm::dvec3(0, 0, 1), "the rotation's axis through the centre"),
       param("rotate_degrees", ParamType::number, 0.0, "counter-clockwise about the axis (right-hand rule)"),
       param("center", ParamType::point, "the fixed point of scale and rotation")
           .optional("the centre of the vertices' bounding box")},
      "V+0, E+0, F+0",
      [](Transaction& tx, const Params& p) {
        transform(tx, options_of(p));
        return Params{};
      },
      [](const Mesh& m, Params& p) { check_transform(m, options_of(p)); })};
}
}  // namespace dlfl

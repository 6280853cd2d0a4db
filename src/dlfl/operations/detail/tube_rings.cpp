// The rings of a tube (see tube_rings.h and connect_faces.h for the curves).
//
// line and hermite: each long edge's two ends are taken relative to their face centroid, the face2 end
// carried back to face1's frame along the curve. In that frame the two offsets are split into a part along
// the curve's start tangent and a part across it; the part across is blended by angle and length (so a
// twisted correspondence turns the ring instead of shrinking it through the axis), the part along linearly.
// The blend is carried to the ring's place by the rotation-minimizing frame of the curve. bezier: each ring
// vertex on its own cubic curve, the rings not turned.

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <numbers>

#include <dlfl/operations/detail/tube_rings.h>

namespace dlfl::detail {
namespace {

// Substeps of the frame transport per segment: enough for the minimal rotations between samples to follow
// the curve's turning.
constexpr int transport_substeps = 16;

glm::dvec3 hermite(const glm::dvec3& p0, const glm::dvec3& t0, const glm::dvec3& p1, const glm::dvec3& t1,
                   double t) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * t0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * t1;
}

glm::dvec3 hermite_derivative(const glm::dvec3& p0, const glm::dvec3& t0, const glm::dvec3& p1,
                              const glm::dvec3& t1, double t) {
  const double t2 = t * t;
  return (6 * t2 - 6 * t) * p0 + (3 * t2 - 4 * t + 1) * t0 + (-6 * t2 + 6 * t) * p1 + (3 * t2 - 2 * t) * t1;
}

// The rotation taking unit vector a to unit vector b about a x b (about some axis across a when opposite).
glm::dmat3 rotation_between(const glm::dvec3& a, const glm::dvec3& b) {
  const double c = glm::dot(a, b);
  if (c < -1.0 + 1e-12) {
    const glm::dvec3 helper = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 e = glm::normalize(glm::cross(a, helper));
    return 2.0 * glm::outerProduct(e, e) - glm::dmat3(1.0);  // a half turn about e
  }
  const glm::dvec3 v = glm::cross(a, b);
  // glm matrices are column-major: this is the cross-product matrix [v]x.
  const glm::dmat3 k(0, v.z, -v.y, -v.z, 0, v.x, v.y, -v.x, 0);
  return glm::dmat3(1.0) + k + (k * k) * (1.0 / (1.0 + c));
}

// v turned by angle phi about the unit axis u, v across u.
glm::dvec3 turn_across(const glm::dvec3& v, const glm::dvec3& u, double phi) {
  return std::cos(phi) * v + std::sin(phi) * glm::cross(u, v);
}

class TubeCurveShape {
 public:
  explicit TubeCurveShape(const TubeRingsInput& in) : in_(in) {
    const double d = glm::distance(in.centroid1, in.centroid2);
    chord_ = in.centroid2 - in.centroid1;
    length_ = d;
    tangent1_ = in.weight1 * d * in.normal1;
    tangent2_ = -in.weight2 * d * in.normal2;  // the tube enters face2 from outside
  }

  glm::dvec3 centre(double t) const {
    if (in_.curve == TubeCurve::line) return in_.centroid1 + t * chord_;
    return hermite(in_.centroid1, tangent1_, in_.centroid2, tangent2_, t);
  }
  // The path of one ring vertex in bezier mode: the same cubic, from corner to corner.
  glm::dvec3 vertex_path(const glm::dvec3& p, const glm::dvec3& q, double t) const {
    return hermite(p, tangent1_, q, tangent2_, t);
  }

  // The unit direction of the curve at t, with fallbacks where its derivative vanishes.
  glm::dvec3 direction(double t) const {
    const glm::dvec3 v = in_.curve == TubeCurve::line
                             ? chord_
                             : hermite_derivative(in_.centroid1, tangent1_, in_.centroid2, tangent2_, t);
    const double n = glm::length(v);
    if (length_ > 0 && n > 1e-9 * length_) return v / n;
    if (length_ > 0) return chord_ / length_;
    if (glm::length(in_.normal1) > 0.5) return glm::normalize(in_.normal1);
    if (glm::length(in_.normal2) > 0.5) return -glm::normalize(in_.normal2);
    return {0, 0, 1};
  }

  // Rotation-minimizing frames at the ring parameters j / s, j = 0..s (frames[0] the identity).
  std::vector<glm::dmat3> frames(int segments) const {
    std::vector<glm::dmat3> out(static_cast<std::size_t>(segments) + 1, glm::dmat3(1.0));
    if (in_.curve == TubeCurve::line) return out;  // the direction does not turn
    const int steps = segments * transport_substeps;
    glm::dmat3 r(1.0);
    glm::dvec3 u = direction(0.0);
    for (int i = 1; i <= steps; ++i) {
      const glm::dvec3 w = direction(double(i) / steps);
      r = rotation_between(u, w) * r;
      u = w;
      if (i % transport_substeps == 0) out[static_cast<std::size_t>(i / transport_substeps)] = r;
    }
    return out;
  }

  double length() const { return length_; }

 private:
  const TubeRingsInput& in_;
  glm::dvec3 chord_{0.0};
  double length_ = 0;
  glm::dvec3 tangent1_{0.0};
  glm::dvec3 tangent2_{0.0};
};

// The pinch and bubble profile of the ring at t: offsets across the curve become scale * r + push * r / |r|.
struct RingShape {
  double scale = 1;
  double push = 0;
};

RingShape ring_shape(const TubeRingsInput& in, double mean_radius, double t) {
  return {1.0 + (in.pinch - 1.0) * 4.0 * t * (1.0 - t),
          in.bubble * mean_radius * 2.0 * std::sqrt(std::max(0.0, t * (1.0 - t)))};
}

glm::dvec3 shaped(const glm::dvec3& across, const RingShape& shape, double tiny) {
  const double r = glm::length(across);
  glm::dvec3 out = shape.scale * across;
  if (r > tiny) out += (shape.push / r) * across;
  return out;
}

// One long edge's two end offsets, split along and across the start direction u0.
struct EndOffsets {
  double along1 = 0, along2 = 0;
  glm::dvec3 across1{0.0}, across2{0.0};
  double radius1 = 0, radius2 = 0;
  double angle = 0;  // from across1 to across2 about u0
  bool turns = false;
};

}  // namespace

std::vector<glm::dvec3> tube_ring_positions(const TubeRingsInput& in) {
  const std::size_t m = in.ends1.size();
  const int s = in.segments;
  std::vector<glm::dvec3> out;
  if (s < 2 || m == 0) return out;
  out.reserve(static_cast<std::size_t>(s - 1) * m);
  const TubeCurveShape curve(in);

  double mean_radius = 0, scale = curve.length();
  for (std::size_t k = 0; k < m; ++k) {
    const double r1 = glm::distance(in.ends1[k], in.centroid1), r2 = glm::distance(in.ends2[k], in.centroid2);
    mean_radius += 0.5 * (r1 + r2) / double(m);
    scale = std::max({scale, r1, r2});
  }
  const double tiny = 1e-12 * scale;

  if (in.curve == TubeCurve::bezier) {
    for (int j = 1; j < s; ++j) {
      const double t = double(j) / s;
      const glm::dvec3 c = curve.centre(t), u = curve.direction(t);
      const RingShape shape = ring_shape(in, mean_radius, t);
      for (std::size_t k = 0; k < m; ++k) {
        const glm::dvec3 o = curve.vertex_path(in.ends1[k], in.ends2[k], t) - c;
        const glm::dvec3 along = glm::dot(o, u) * u;
        out.push_back(c + along + shaped(o - along, shape, tiny));
      }
    }
    return out;
  }

  const std::vector<glm::dmat3> frames = curve.frames(s);
  const glm::dmat3 back_from_end = glm::transpose(frames.back());
  const glm::dvec3 u0 = curve.direction(0.0);
  std::vector<EndOffsets> offsets(m);
  double sum_sin = 0, sum_cos = 0;
  for (std::size_t k = 0; k < m; ++k) {
    EndOffsets& e = offsets[k];
    const glm::dvec3 o1 = in.ends1[k] - in.centroid1, o2 = back_from_end * (in.ends2[k] - in.centroid2);
    e.along1 = glm::dot(o1, u0);
    e.along2 = glm::dot(o2, u0);
    e.across1 = o1 - e.along1 * u0;
    e.across2 = o2 - e.along2 * u0;
    e.radius1 = glm::length(e.across1);
    e.radius2 = glm::length(e.across2);
    e.turns = e.radius1 > tiny && e.radius2 > tiny;
    if (e.turns) {
      e.angle = std::atan2(glm::dot(u0, glm::cross(e.across1, e.across2)), glm::dot(e.across1, e.across2));
      sum_sin += std::sin(e.angle);
      sum_cos += std::cos(e.angle);
    }
  }
  // Every vertex turns the same way round: each angle is taken within half a turn of their circular mean.
  const double mean_angle = std::atan2(sum_sin, sum_cos);
  for (EndOffsets& e : offsets) {
    if (e.turns)
      e.angle += 2 * std::numbers::pi * std::round((mean_angle - e.angle) / (2 * std::numbers::pi));
  }

  for (int j = 1; j < s; ++j) {
    const double t = double(j) / s;
    const glm::dvec3 c = curve.centre(t);
    const glm::dmat3& frame = frames[static_cast<std::size_t>(j)];
    const RingShape shape = ring_shape(in, mean_radius, t);
    for (const EndOffsets& e : offsets) {
      const glm::dvec3 across = e.turns ? ((1 - t) * e.radius1 + t * e.radius2) / e.radius1 *
                                              turn_across(e.across1, u0, t * e.angle)
                                        : (1 - t) * e.across1 + t * e.across2;
      const glm::dvec3 local = shaped(across, shape, tiny) + ((1 - t) * e.along1 + t * e.along2) * u0;
      out.push_back(c + frame * local);
    }
  }
  return out;
}

}  // namespace dlfl::detail

// extrude_face: the extrusion family of TopMod (DLFLExtrude), each style a sequence of stages grown with the
// Euler operators (detail/extrusion_rings.h). The geometry of a face's extrusion is planned first from its
// positions alone, so that the checks see every new position before anything changes.

#include <dlfl/operations/extrude_face.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <numbers>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/geometry.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/detail/extrusion_faces.h>
#include <dlfl/operations/detail/extrusion_rings.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "extrude_face";
constexpr int max_segments = 10000;
constexpr double phi = std::numbers::phi;

struct StyleName {
  ExtrudeStyle style;
  std::string_view name;
};
constexpr std::array style_names = {
    StyleName{ExtrudeStyle::cubical, "cubical"},
    StyleName{ExtrudeStyle::doo_sabin, "doo-sabin"},
    StyleName{ExtrudeStyle::octahedral, "octahedral"},
    StyleName{ExtrudeStyle::stellate, "stellate"},
    StyleName{ExtrudeStyle::double_stellate, "double-stellate"},
    StyleName{ExtrudeStyle::dodecahedral, "dodecahedral"},
    StyleName{ExtrudeStyle::icosahedral, "icosahedral"},
    StyleName{ExtrudeStyle::dome, "dome"},
};

// The styles that end in a cone, with no moved face to extrude again.
bool ends_in_cone(ExtrudeStyle s) {
  return s == ExtrudeStyle::stellate || s == ExtrudeStyle::double_stellate || s == ExtrudeStyle::dome;
}
// The styles whose only new point over the face is an apex: nothing to turn or scale.
bool moves_a_point(ExtrudeStyle s) {
  return s == ExtrudeStyle::stellate || s == ExtrudeStyle::double_stellate;
}

// ---- geometry ------------------------------------------------------------------------------------------

// One segment's share of the motion: `height` along the unit `direction`, turned by `angle` (radians) and
// scaled by `scale` about the moving centroid.
struct Motion {
  glm::dvec3 direction;
  double height;
  double angle;
  double scale;
};

// v turned by `angle` about the unit `axis` (Rodrigues), counter-clockwise seen from the axis' tip.
glm::dvec3 turned(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
  if (angle == 0.0) return v;
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(axis, v) * s + axis * (glm::dot(axis, v) * (1.0 - c));
}

// The point q of a base of centroid `centre`, carried the fraction `lambda` through a segment: raised by
// lambda of its height, its offset from the centre spread by `spread`, scaled by scale^lambda and turned by
// lambda of its angle. lambda = 1 is the segment's end: all the rings of a style lie between.
glm::dvec3 carried(const Motion& m, const glm::dvec3& centre, const glm::dvec3& q, double lambda,
                   double spread) {
  const glm::dvec3 offset = (q - centre) * (spread * std::pow(m.scale, lambda));
  return centre + m.direction * (lambda * m.height) + turned(offset, m.direction, lambda * m.angle);
}

glm::dvec3 centroid(const std::vector<glm::dvec3>& ring) {
  glm::dvec3 sum(0.0);
  for (const auto& p : ring) sum += p;
  return sum / double(ring.size());
}

// The midpoint of edge i, from p_i to p_{i+1}.
std::vector<glm::dvec3> midpoints(const std::vector<glm::dvec3>& ring) {
  std::vector<glm::dvec3> out(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) out[i] = 0.5 * (ring[i] + ring[(i + 1) % ring.size()]);
  return out;
}

// Doo-Sabin's mask for a face (as TopMod's extrudeFaceDS): p'_i = sum_j a_ij p_j with a_ii = 1/4 + 5/(4n),
// a_ij = (3 + 2 cos(2 pi (i - j) / n)) / (4n). The cosine sum splits as cos(t i) C + sin(t i) S with
// C = sum cos(t j) p_j and S = sum sin(t j) p_j, so this is O(n), not O(n^2). It keeps the centroid and
// halves a regular polygon.
std::vector<glm::dvec3> doo_sabin_points(const std::vector<glm::dvec3>& ring) {
  const std::size_t n = ring.size();
  const double t = 2.0 * std::numbers::pi / double(n);
  glm::dvec3 sum(0.0), c(0.0), s(0.0);
  for (std::size_t j = 0; j < n; ++j) {
    sum += ring[j];
    c += std::cos(t * double(j)) * ring[j];
    s += std::sin(t * double(j)) * ring[j];
  }
  std::vector<glm::dvec3> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = 0.25 * ring[i] + (0.75 / double(n)) * sum +
             (0.5 / double(n)) * (std::cos(t * double(i)) * c + std::sin(t * double(i)) * s);
  }
  return out;
}

// Midpoints spread by this lie on the circumcircle of a regular polygon; a 2-gon's have no such circle.
double midpoint_spread(std::size_t n) { return n >= 3 ? 1.0 / std::cos(std::numbers::pi / double(n)) : 1.0; }

// ---- the plan: stages and their positions --------------------------------------------------------------

struct Stage {
  enum class Kind : std::uint8_t {
    quad_ring,      // grow_quad_ring on the current face, which becomes the inner face
    triangle_ring,  // grow_triangle_ring, likewise
    cone,           // grow_cone on the current face, which is used up
    cones_on_base,  // a cone on the face of each corner of the face the last cone grew on
    cones_across,   // a cone on the face across each edge of the current face
  };
  Kind kind;
  // After growing a ring: delete the edges of the face it grew on, merging each new face with the one of the
  // previous ring beside it (the pentagons of the dodecahedral and icosahedral styles).
  bool merge_base = false;
  std::vector<glm::dvec3> positions;
};
using Plan = std::vector<Stage>;

// TopMod's dome: the rings' heights and widths (after Doo-Sabin's halving), then the cap; the heights are
// taken as shares of their sum, so that the dome is `distance` high.
constexpr std::array dome_heights = {0.3, 0.18, 0.1, 0.05, 0.025};
constexpr std::array dome_widths = {1.7, 1.6, 1.4, 1.2, 1.1};
constexpr double dome_cap = 0.01;
constexpr double dome_total = 0.3 + 0.18 + 0.1 + 0.05 + 0.025 + dome_cap;

Plan plan_of(std::vector<glm::dvec3> ring, const glm::dvec3& direction, const ExtrudeFaceOptions& o) {
  const std::size_t n = ring.size();
  const int segments = o.segments;
  const Motion m{direction, o.distance / segments, glm::radians(o.rotate_degrees) / segments,
                 std::pow(o.scale, 1.0 / segments)};
  const double k = midpoint_spread(n);
  Plan plan;
  // n positions, the i-th from point(i).
  const auto each = [n](auto&& point) {
    std::vector<glm::dvec3> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = point(i);
    return out;
  };
  const auto next = [n](std::size_t i) { return (i + 1) % n; };
  switch (o.style) {
    case ExtrudeStyle::cubical:
    case ExtrudeStyle::doo_sabin:
    case ExtrudeStyle::octahedral:
      for (int s = 0; s < segments; ++s) {
        const glm::dvec3 c = centroid(ring);
        if (o.style == ExtrudeStyle::octahedral) {
          const auto mid = midpoints(ring);
          ring = each([&](std::size_t i) { return carried(m, c, mid[i], 1.0, k); });
          plan.push_back({Stage::Kind::triangle_ring, false, ring});
        } else {
          if (o.style == ExtrudeStyle::doo_sabin) ring = doo_sabin_points(ring);
          ring = each([&](std::size_t i) { return carried(m, c, ring[i], 1.0, 1.0); });
          plan.push_back({Stage::Kind::quad_ring, false, ring});
        }
      }
      break;
    case ExtrudeStyle::dodecahedral:
    case ExtrudeStyle::icosahedral:
      // The layers of the regular solid standing on a face: heights 1/phi^2, 1/phi and 1 of the whole, at
      // phi, phi and 1 times the face's circumradius, over its corners or its edges in turn.
      for (int s = 0; s < segments; ++s) {
        const glm::dvec3 c = centroid(ring);
        const auto mid = midpoints(ring);
        const auto top = each([&](std::size_t i) { return carried(m, c, mid[i], 1.0, k); });
        if (o.style == ExtrudeStyle::dodecahedral) {
          plan.push_back({Stage::Kind::quad_ring, false, each([&](std::size_t i) {
                            return carried(m, c, ring[i], 1.0 / (phi * phi), phi);
                          })});
          plan.push_back({Stage::Kind::triangle_ring, true,
                          each([&](std::size_t i) { return carried(m, c, mid[i], 1.0 / phi, phi * k); })});
          plan.push_back({Stage::Kind::quad_ring, true, top});
        } else {
          plan.push_back({Stage::Kind::triangle_ring, false, each([&](std::size_t i) {
                            return carried(m, c, mid[i], 1.0 / (phi * phi), phi * k);
                          })});
          plan.push_back({Stage::Kind::quad_ring, true, top});
          // The pentagon across top edge i holds old corner i+1; its apex stands over that corner.
          plan.push_back({Stage::Kind::cones_across, false,
                          each([&](std::size_t i) { return carried(m, c, ring[next(i)], 1.0 / phi, phi); })});
        }
        ring = top;
      }
      break;
    case ExtrudeStyle::stellate:
    case ExtrudeStyle::double_stellate: {
      const glm::dvec3 c = centroid(ring);
      plan.push_back({Stage::Kind::cone, false, {c + direction * o.distance}});
      if (o.style == ExtrudeStyle::double_stellate) {
        // The second apexes where TopMod's zero-height stellations put them, before the first one rises.
        plan.push_back({Stage::Kind::cones_on_base, false,
                        each([&](std::size_t i) { return (c + ring[i] + ring[next(i)]) / 3.0; })});
      }
      break;
    }
    case ExtrudeStyle::dome: {
      for (std::size_t r = 0; r < dome_heights.size(); ++r) {
        const Motion ring_motion{direction, o.distance * dome_heights[r] / dome_total,
                                 glm::radians(o.rotate_degrees) / double(dome_heights.size()),
                                 dome_widths[r] * std::pow(o.scale, 1.0 / double(dome_heights.size()))};
        const glm::dvec3 c = centroid(ring);
        const auto shrunk = doo_sabin_points(ring);
        ring = each([&](std::size_t i) { return carried(ring_motion, c, shrunk[i], 1.0, 1.0); });
        plan.push_back({Stage::Kind::quad_ring, false, ring});
      }
      plan.push_back(
          {Stage::Kind::cone, false, {centroid(ring) + direction * (o.distance * dome_cap / dome_total)}});
      break;
    }
  }
  return plan;
}

bool finite(const Plan& plan) {
  for (const Stage& s : plan) {
    for (const auto& p : s.positions) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    }
  }
  return true;
}

// ---- checks --------------------------------------------------------------------------------------------

// v scaled to length 1, or nothing if it has no direction (zero, or too large or small to scale).
std::optional<glm::dvec3> unit(const glm::dvec3& v) {
  const double big = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(big > 0.0) || !std::isfinite(big)) return std::nullopt;
  const glm::dvec3 w = v / big;
  return w / glm::length(w);
}

std::string shown(const glm::dvec3& p) {
  return format_number(p.x) + "," + format_number(p.y) + "," + format_number(p.z);
}

void check_options(const ExtrudeFaceOptions& o) {
  const auto not_finite = [](double x) { return !std::isfinite(x); };
  if (not_finite(o.distance))
    detail::refuse_worded(op_name, "distance", " = " + format_number(o.distance) + " is not finite");
  if (not_finite(o.rotate_degrees))
    detail::refuse_worded(op_name, "rotate_degrees",
                          " = " + format_number(o.rotate_degrees) + " is not finite");
  if (not_finite(o.scale) || !(o.scale > 0.0))
    detail::refuse_worded(op_name, "scale", " = " + format_number(o.scale) + " is outside (0, inf)");
  if (o.segments < 1 || o.segments > max_segments) {
    detail::refuse_worded(
        op_name, "segments",
        " = " + std::to_string(o.segments) + " is outside [1, " + std::to_string(max_segments) + "]");
  }
  const std::string style(to_string(o.style));
  if (ends_in_cone(o.style) && o.segments != 1) {
    detail::refuse_worded(
        op_name, "segments",
        " = " + std::to_string(o.segments) + ": style " + style + " ends in a cone, so it takes 1");
  }
  if (moves_a_point(o.style) && o.rotate_degrees != 0.0) {
    detail::refuse_worded(
        op_name, "rotate_degrees",
        " = " + format_number(o.rotate_degrees) + ": style " + style + " has no face to turn, so it takes 0");
  }
  if (moves_a_point(o.style) && o.scale != 1.0) {
    detail::refuse_worded(
        op_name, "scale",
        " = " + format_number(o.scale) + ": style " + style + " has no face to scale, so it takes 1");
  }
  if (o.direction && !unit(*o.direction)) {
    detail::refuse_worded(op_name, "direction",
                          " = " + shown(*o.direction) + " gives no direction (a zero vector)");
  }
}

struct FacePlan {
  FaceId face;
  Plan plan;
};

// Every face's plan, each checked; refusals of a face name `parameter`.
std::vector<FacePlan> planned(const Mesh& mesh, std::span<const FaceId> faces, const ExtrudeFaceOptions& o,
                              std::string_view parameter) {
  check_options(o);
  detail::check_surface_faces(op_name, mesh, faces, parameter);
  std::vector<FacePlan> out;
  out.reserve(faces.size());
  for (FaceId f : faces) {
    const std::optional<glm::dvec3> direction =
        o.direction ? unit(*o.direction) : unit(newell_vector(mesh, f));
    if (!direction) {
      detail::refuse_worded(
          op_name, parameter,
          ": " + to_string(f) + " has no normal (its Newell vector is zero); give a direction");
    }
    std::vector<glm::dvec3> ring;
    for (VertexId v : vertices(mesh, f)) ring.push_back(mesh.position(v));
    Plan plan = plan_of(ring, *direction, o);
    if (!finite(plan)) {
      // Blame what makes the difference: the face itself (even unmoved), else the distance (the face only
      // scaled and turned stays finite), else the scale.
      ExtrudeFaceOptions unmoved{0.0, o.segments, 0.0, 1.0, {}, o.style};
      ExtrudeFaceOptions not_raised = o;
      not_raised.distance = 0.0;
      const std::string name = !finite(plan_of(ring, *direction, unmoved))     ? std::string(parameter)
                               : finite(plan_of(ring, *direction, not_raised)) ? "distance"
                                                                               : "scale";
      detail::refuse_worded(op_name, name, ": the new positions on " + to_string(f) + " would not be finite");
    }
    out.push_back({f, std::move(plan)});
  }
  return out;
}

// ---- building ------------------------------------------------------------------------------------------

ExtrudeFaceResult build(Transaction& tx, const FacePlan& fp) {
  const Mesh& m = tx.mesh();
  std::vector<CornerId> face = detail::corners_from(m, m.first_corner(fp.face));  // as the plan read it
  std::vector<CornerId> previous;
  ExtrudeFaceResult result;
  for (const Stage& s : fp.plan) {
    switch (s.kind) {
      case Stage::Kind::quad_ring:
      case Stage::Kind::triangle_ring: {
        std::vector<CornerId> inner = s.kind == Stage::Kind::quad_ring
                                          ? detail::grow_quad_ring(tx, face, s.positions)
                                          : detail::grow_triangle_ring(tx, face, s.positions);
        if (s.merge_base) detail::remove_edges_of(tx, face);
        previous = std::move(face);
        face = std::move(inner);
        break;
      }
      case Stage::Kind::cone:
        result.apex = detail::grow_cone(tx, face, s.positions[0]);
        previous = std::move(face);
        face.clear();
        break;
      case Stage::Kind::cones_on_base:
        for (std::size_t i = 0; i < previous.size(); ++i)
          detail::grow_cone(tx, detail::corners_from(m, previous[i]), s.positions[i]);
        break;
      case Stage::Kind::cones_across:
        for (std::size_t i = 0; i < face.size(); ++i)
          detail::grow_cone(tx, detail::corners_from(m, m.opposite(face[i])), s.positions[i]);
        break;
    }
  }
  if (!face.empty()) result.end_face = m.face(face[0]);
  return result;
}

ExtrudeStyle style_named(const std::string& name) {
  for (const auto& s : style_names) {
    if (s.name == name) return s.style;
  }
  detail::refuse_worded(op_name, "style", " = '" + name + "' is not a style");
}

ExtrudeFaceOptions options_of(const Params& p) {
  ExtrudeFaceOptions o;
  o.distance = p.number("distance");
  o.segments = static_cast<int>(std::clamp<std::int64_t>(p.integer("segments"), -1, max_segments + 1));
  o.rotate_degrees = p.number("rotate_degrees");
  o.scale = p.number("scale");
  if (p.has("direction")) o.direction = p.point("direction");
  o.style = style_named(p.text("style"));
  return o;
}

}  // namespace

std::string_view to_string(ExtrudeStyle style) {
  for (const auto& s : style_names) {
    if (s.style == style) return s.name;
  }
  return "unknown";
}

ExtrudeFaceResult extrude_face(Transaction& tx, FaceId face, const ExtrudeFaceOptions& options) {
  return extrude_faces(tx, std::span<const FaceId>(&face, 1), options, "face").front();
}

std::vector<ExtrudeFaceResult> extrude_faces(Transaction& tx, std::span<const FaceId> faces,
                                             const ExtrudeFaceOptions& options,
                                             std::string_view face_parameter) {
  return detail::build_each(tx, planned(tx.mesh(), faces, options, face_parameter), &build);
}

std::vector<OperationSpec> detail::extrude_face_operation_specs() {
  std::vector<std::string> styles;
  for (const auto& s : style_names) styles.emplace_back(s.name);
  return {face_operation(
      op_name,
      "moves a face out along a direction and joins it to where it was, in one of TopMod's extrusion styles",
      "the face to extrude", "faces to extrude, each on its own",
      {param("distance", ParamType::number, 1.0, "how far the face moves (in all, whatever the segments)"),
       param("segments", ParamType::integer, 1, "how many times the style's unit is built along the way")
           .in(1, max_segments),
       param("rotate_degrees", ParamType::number, 0.0,
             "the moved face turns by this about the direction (counter-clockwise seen from its tip)"),
       param("scale", ParamType::number, 1.0, "the moved face is scaled by this about its centroid")
           .range(0.0, std::numeric_limits<double>::infinity(), true, false),
       param("direction", ParamType::point, "where the face moves (normalised)")
           .optional("the face's normal"),
       param("style", ParamType::text, "cubical", "what joins the moved face to where it was")
           .one_of(styles)},
      "per face of n sides, s segments: cubical, doo-sabin: V+n*s, E+2n*s, F+n*s; octahedral: V+n*s, E+3n*s, "
      "F+2n*s; stellate: V+1, E+n, F+n-1; double-stellate: V+n+1, E+4n, F+3n-1; dodecahedral: V+3n*s, "
      "E+5n*s, "
      "F+2n*s; icosahedral: V+3n*s, E+9n*s, F+6n*s; dome: V+5n+1, E+11n, F+6n-1",
      [](Transaction& tx, const FaceSelection& selection, const Params& p) {
        const auto results = extrude_faces(tx, selection.faces, options_of(p), selection.parameter);
        std::vector<FaceId> ends;
        std::vector<VertexId> apexes;
        for (const auto& r : results) {
          if (r.end_face.valid()) ends.push_back(r.end_face);
          if (r.apex.valid()) apexes.push_back(r.apex);
        }
        Params out;
        put_made(out, "faces", "face", ends, selection.parameter == "face");
        put_made(out, "vertices", "vertex", apexes, selection.parameter == "face");
        return out;
      },
      [](const Mesh& mesh, const FaceSelection& selection, const Params& p) {
        planned(mesh, selection.faces, options_of(p), selection.parameter);
      })};
}
}  // namespace dlfl

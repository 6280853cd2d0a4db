#include <dlfl/schemes/zhang_wang_honeycomb.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/schemes/detail/boundary_params.h>
#include <dlfl/schemes/detail/honeycomb_params.h>
#include <dlfl/schemes/detail/honeycomb_planarize.h>
#include <dlfl/schemes/detail/honeycomb_remesh.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {
namespace {

void check_unit(const char* name, double x) {
  if (!(x >= 0.0 && x <= 1.0)) {
    throw InvalidArgument(std::string("honeycomb-zw: parameter ") + name + " = " + format_number(x) +
                          " is outside [0, 1]");
  }
}

glm::dvec3 centroid(const Mesh& mesh, FaceId f) {
  glm::dvec3 sum(0.0);
  for (CornerId c : mesh.corners(f)) sum += mesh.position(mesh.vertex(c));
  return sum / double(mesh.size(f));
}

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
const glm::dvec3 unset_point(nan, nan, nan);

bool is_set(const glm::dvec3& p) { return !std::isnan(p.x) && !std::isnan(p.y) && !std::isnan(p.z); }

// The new control points are finite for finite input; the check keeps the promise of set_face_point (and
// the old behaviour, which went through it) should an overflow make one infinite.
const glm::dvec3& check_finite(const glm::dvec3& p, FaceId f) {
  if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) {
    throw InvalidArgument("honeycomb-zw: the control point of " + to_string(f) + " is not finite");
  }
  return p;
}

void require_face(const Mesh& mesh, FaceId f, const char* op) {
  if (!mesh.is_alive(f)) throw InvalidArgument(std::string(op) + ": " + to_string(f) + " does not exist");
}

// The control points, read once per mesh rather than looked up by name per face.
class ControlPoints {
 public:
  explicit ControlPoints(const Mesh& mesh)
      : mesh_(mesh), points_(mesh.find_attribute<FaceId, glm::dvec3>(face_point_attribute)) {}
  glm::dvec3 point_or_centroid(FaceId f) const {
    if (points_ && is_set((*points_)[f])) return (*points_)[f];
    return centroid(mesh_, f);
  }

 private:
  const Mesh& mesh_;
  std::optional<ConstAttribute<FaceId, glm::dvec3>> points_;
};

double half_angle_cosine(int n, double b, const char* what) {
  if (n < 3) throw InvalidArgument(std::string(what) + ": needs n >= 3, got " + std::to_string(n));
  check_unit("b", b);
  return std::cos(std::numbers::pi / double(n));
}

}  // namespace

std::optional<glm::dvec3> face_point(const Mesh& mesh, FaceId f) {
  require_face(mesh, f, "face_point");
  const auto points = mesh.find_attribute<FaceId, glm::dvec3>(face_point_attribute);
  if (!points || !is_set((*points)[f])) return std::nullopt;
  return (*points)[f];
}

glm::dvec3 face_point_or_centroid(const Mesh& mesh, FaceId f) {
  require_face(mesh, f, "face_point_or_centroid");
  return ControlPoints(mesh).point_or_centroid(f);
}

glm::dvec3 unset_face_point() { return unset_point; }

void set_face_point(Mesh& mesh, FaceId f, const std::optional<glm::dvec3>& point) {
  require_face(mesh, f, "set_face_point");
  if (point && !(std::isfinite(point->x) && std::isfinite(point->y) && std::isfinite(point->z))) {
    throw InvalidArgument("set_face_point: control point of " + to_string(f) + " is not finite");
  }
  if (!point) {
    if (auto points = mesh.find_attribute<FaceId, glm::dvec3>(face_point_attribute))
      (*points)[f] = unset_point;
    return;
  }
  mesh.add_face_attribute<glm::dvec3>(face_point_attribute, unset_point)[f] = *point;
}

double zhang_wang_a(const ZhangWangParams& p, int n) {
  if (n < 2) throw InvalidArgument("zhang_wang_a: needs n >= 2, got " + std::to_string(n));
  return p.a ? *p.a : (4.0 - std::cos(2.0 * std::numbers::pi / double(n))) / 9.0;
}

void check_zhang_wang_params(const ZhangWangParams& p) {
  if (p.a) check_unit("a", *p.a);
  check_unit("b", p.b);
  check_unit("c", p.c);
  check_unit("alpha", p.alpha);
}

Mesh zhang_wang_honeycomb(const Mesh& mesh, const ZhangWangParams& p, Origins* origins) {
  check_zhang_wang_params(p);

  // The CCV of every input face: its control point, or its centroid.
  std::vector<glm::dvec3> ccv(mesh.face_capacity());
  const ControlPoints control(mesh);
  for (FaceId f : mesh.faces()) ccv[f.index()] = control.point_or_centroid(f);

  const double b = p.b;
  const auto face_points = [&](FaceId f, std::span<const CornerId> corners, std::span<glm::dvec3> points) {
    const glm::dvec3 q = ccv[f.index()];
    const std::size_t n = corners.size();
    for (std::size_t i = 0; i < n; ++i) {  // formula (2): the point of the edge from p_i to p_{i+1}
      const glm::dvec3 mid =
          0.5 * (mesh.position(mesh.vertex(corners[i])) + mesh.position(mesh.vertex(corners[(i + 1) % n])));
      points[i] = (1.0 - b) * q + b * mid;
    }
  };
  detail::HoneycombRemesh out =
      detail::honeycomb_remesh(mesh, face_points, true, p.boundary, "honeycomb-zw", origins);
  // Under the boundary rule a hole is no face: it has no CCV of its own and lends none to its vertices.
  const bool curve = p.boundary.rule == BoundaryRule::curve;
  Mesh& result = out.mesh;
  const FaceAttribute<glm::dvec3> result_points =
      result.add_face_attribute<glm::dvec3>(face_point_attribute, unset_point);
  // Every face gets a point: writing the last slot first sizes the storage once, instead of growing it with
  // each write in handle order.
  if (result.face_capacity() > 0) result_points[FaceId(result.face_capacity() - 1)] = unset_point;

  // Formula (3): the shrunken copy of each face.
  for (FaceId f : mesh.faces()) {
    const FaceId copy = out.face_of_face[f.index()];
    if (!copy.valid() || (curve && mesh.is_hole(f))) continue;  // a point sphere, or a boundary loop
    const double a = zhang_wang_a(p, int(mesh.size(f)));
    result_points[copy] = check_finite((1.0 - a) * ccv[f.index()] + a * centroid(mesh, f), copy);
  }

  // Formula (4): sums over the neighbours and the faces around each vertex, one corner at a time (the corner
  // c at v has the neighbour vertex(next(c)) along its outgoing edge and the face face(c)). Under the
  // boundary rule a boundary vertex of valence n has n neighbours but fewer faces: the CCVs' share 1 - alpha
  // is spread over the faces it has (all of it goes to the neighbours if it has none).
  std::vector<glm::dvec3> neighbour_sum(mesh.vertex_capacity(), glm::dvec3(0.0));
  std::vector<glm::dvec3> ccv_sum(mesh.vertex_capacity(), glm::dvec3(0.0));
  std::vector<std::uint32_t> valence(mesh.vertex_capacity(), 0), faces(curve ? mesh.vertex_capacity() : 0, 0);
  for (CornerId c : mesh.corners()) {
    if (!mesh.edge(c).valid()) continue;  // a point sphere
    const std::uint32_t v = mesh.vertex(c).index();
    neighbour_sum[v] += mesh.position(mesh.vertex(mesh.next(c)));
    ++valence[v];
    if (curve && mesh.is_hole(mesh.face(c))) continue;
    ccv_sum[v] += ccv[mesh.face(c).index()];
    if (curve) ++faces[v];
  }
  for (VertexId v : mesh.vertices()) {
    const std::uint32_t n = valence[v.index()];
    if (n == 0) continue;  // a point sphere: copied without a CCV
    const std::uint32_t k = curve ? faces[v.index()] : n;
    const glm::dvec3 average =
        k == n   ? (p.alpha * neighbour_sum[v.index()] + (1.0 - p.alpha) * ccv_sum[v.index()]) / double(n)
        : k == 0 ? neighbour_sum[v.index()] / double(n)
                 : p.alpha * neighbour_sum[v.index()] / double(n) +
                       (1.0 - p.alpha) * ccv_sum[v.index()] / double(k);
    const FaceId around = out.face_of_vertex[v.index()];
    result_points[around] = check_finite((1.0 - p.c) * mesh.position(v) + p.c * average, around);
  }
  if (p.planarize && detail::lateral_rule_applies(mesh) && detail::planarize_new_faces(result)) {
    // A CCV off its face's plane would bend the face's copy at the next step.
    for (FaceId f : result.faces()) {
      const FacePlane plane = face_plane(result, f);
      if (result.is_hole(f) || !is_set(result_points[f]) || plane.normal == glm::dvec3(0.0)) continue;
      result_points[f] -= plane.normal * plane.distance(result_points[f]);
    }
  }
  return std::move(out.mesh);
}

glm::dvec3 zhang_wang_limit_point(const Mesh& mesh, FaceId f, const ZhangWangParams& p) {
  check_zhang_wang_params(p);
  if (!mesh.is_alive(f)) throw InvalidArgument("zhang_wang_limit_point: " + to_string(f) + " does not exist");
  const std::uint32_t n = mesh.size(f);
  if (n < 2) throw InvalidArgument("zhang_wang_limit_point: " + to_string(f) + " is a point sphere");
  const double a = zhang_wang_a(p, int(n)), b = p.b;
  const double denominator = 1.0 + a - b;
  if (!(denominator > 0.0)) {
    throw InvalidArgument(
        "zhang_wang_limit_point: with a = 0 and b = 1 a face's centre never moves, so it has "
        "no single limit");
  }
  return ((1.0 - b) * ControlPoints(mesh).point_or_centroid(f) + a * centroid(mesh, f)) / denominator;
}

TensionBounds zhang_wang_paper_bounds(int n, double b) {
  const double c = half_angle_cosine(n, b, "zhang_wang_paper_bounds");
  return {c / (1.0 + c) * b, c / (1.0 - c) * b};
}

TensionBounds zhang_wang_eigen_bounds(int n, double b) {
  const double c = half_angle_cosine(n, b, "zhang_wang_eigen_bounds");
  return {b * (1.0 - c), b * (1.0 + c)};
}

namespace detail {

SchemeSpec zhang_wang_honeycomb_scheme() {
  // The tension a is a number, or "symmetric" for the paper's a_n = (4 - cos(2 pi / n)) / 9.
  constexpr const char* symmetric = "symmetric";
  const ZhangWangParams d;
  std::vector<ParamSpec> specs = with_planarize_param(with_boundary_params({
      param("a", ParamType::number, symmetric,
            "the tension a_n of formula (3); 'symmetric': the paper's (4 - cos(2 pi / n)) / 9")
          .in(0, 1)
          .one_of({symmetric}),
      param("b", ParamType::number, d.b,
            "b_n of formula (2): each new edge vertex between the face's CCV (0) and the edge midpoint (1)")
          .in(0, 1),
      param("c", ParamType::number, d.c,
            "c_n of formula (4): the CCV of a vertex's new face between the vertex (0) and its "
            "neighbourhood (1)")
          .in(0, 1),
      param("alpha", ParamType::number, d.alpha,
            "the weight of the neighbours in formula (4); the CCVs around get 1 - alpha")
          .in(0, 1),
  }));
  return {"honeycomb-zw",
          "Zhang-Wang honeycomb: the honeycomb's topology, every face carrying a central control vertex",
          std::move(specs),
          {},
          [](const Mesh& m, const Params& p, Origins* origins) {
            ZhangWangParams z;
            if (p.get("a").kind() != Value::Kind::text) z.a = p.number("a");  // else the keyword
            z.b = p.number("b");
            z.c = p.number("c");
            z.alpha = p.number("alpha");
            z.boundary = boundary_options_from(p);
            z.planarize = p.has("planarize") && p.integer("planarize") == 1;
            return zhang_wang_honeycomb(m, z, origins);
          },
          [](const MeshCounts& c, const Params&) { return honeycomb_counts(c); }};
}

}  // namespace detail
}  // namespace dlfl

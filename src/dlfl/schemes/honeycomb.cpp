#include <dlfl/schemes/honeycomb.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/schemes/detail/boundary_params.h>
#include <dlfl/schemes/detail/honeycomb_params.h>
#include <dlfl/schemes/detail/honeycomb_planarize.h>
#include <dlfl/schemes/detail/honeycomb_remesh.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {
namespace {

// Faces up to this size use the circulant weights directly, O(N^2) from a table built once per size; larger
// faces use the closed form of the cosine sum, O(N), so a huge hole face cannot make a step quadratic.
constexpr std::uint32_t direct_max = 64;

// What the parameter check and the reservation need to know about the faces, in one pass.
struct FaceSummary {
  std::uint32_t min_size = std::numeric_limits<std::uint32_t>::max();  // over faces of 2 or more corners
  std::uint32_t max_size = 0;
  std::size_t polygon_faces = 0;    // faces of 2 or more corners (holes included)
  std::size_t polygon_corners = 0;  // their corners
  std::size_t point_spheres = 0;    // faces of 1 corner
};

// Under the boundary rule a hole's points come from the boundary polygon, not from formula (2), so its size
// does not constrain the tension (`skip_holes`).
FaceSummary summarize(const Mesh& mesh, bool skip_holes) {
  FaceSummary s;
  for (FaceId f : mesh.faces()) {
    const std::uint32_t n = mesh.size(f);
    if (skip_holes && mesh.is_hole(f)) continue;
    if (n == 1) {
      ++s.point_spheres;
      continue;
    }
    ++s.polygon_faces;
    s.polygon_corners += n;
    s.min_size = std::min(s.min_size, n);
    s.max_size = std::max(s.max_size, n);
  }
  return s;
}

bool in_open_unit(double x) { return x > 0.0 && x < 1.0; }  // false for NaN

void check_params(const FaceSummary& s, const HoneycombParams& p) {
  if (!(p.t >= 0.0 && p.t <= 1.0))
    throw InvalidArgument("honeycomb: parameter t = " + format_number(p.t) + " is outside [0, 1]");
  if (p.a) {
    if (!in_open_unit(*p.a))
      throw InvalidArgument("honeycomb: parameter a = " + format_number(*p.a) + " is outside (0, 1)");
    return;
  }
  if (s.polygon_faces == 0) return;
  // a0 + a1/N is monotonic in N, so it lies in the (convex) interval (0, 1) for every size present as soon
  // as it does for the smallest and the largest.
  for (std::uint32_t n : {s.min_size, s.max_size}) {
    const double a = honeycomb_tension(p, int(n));
    if (!in_open_unit(a)) {
      throw InvalidArgument("honeycomb: tension a0 + a1/N = " + format_number(a) + " for a " +
                            std::to_string(n) + "-sided face is outside (0, 1) (parameters a0, a1)");
    }
  }
}

// beta (1 - a) / (3N - 5) for the index difference k = n - m mod N, k != 0.
double off_diagonal(std::uint32_t N, std::uint32_t k, double a) {
  const double beta = 3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * double(k) / double(N));
  return beta * (1.0 - a) / (3.0 * double(N) - 5.0);
}

// Row weights w[k] = a_{n, n-k} per face size N <= direct_max, built on first use.
class WeightTable {
 public:
  explicit WeightTable(const HoneycombParams& p) : params_(p) {}
  const double* row(std::uint32_t N) {
    double* w = weights_[N].data();
    if (!ready_[N]) {
      const double a = honeycomb_tension(params_, int(N));
      w[0] = a;
      for (std::uint32_t k = 1; k < N; ++k) w[k] = off_diagonal(N, k, a);
      ready_[N] = true;
    }
    return w;
  }

 private:
  const HoneycombParams& params_;
  std::array<bool, direct_max + 1> ready_{};
  std::array<std::array<double, direct_max>, direct_max + 1> weights_{};
};

}  // namespace

double honeycomb_coefficient(int N, int n, int m, double a) {
  if (N < 2 || n < 0 || m < 0 || n >= N || m >= N) {
    throw InvalidArgument("honeycomb_coefficient: needs N >= 2 and 0 <= n, m < N, got N = " +
                          std::to_string(N) + ", n = " + std::to_string(n) + ", m = " + std::to_string(m));
  }
  if (n == m) return a;
  return off_diagonal(std::uint32_t(N), std::uint32_t((n - m + N) % N), a);
}

double honeycomb_tension(const HoneycombParams& p, int N) { return p.a ? *p.a : p.a0 + p.a1 / double(N); }

void check_honeycomb_params(const Mesh& mesh, const HoneycombParams& p) {
  check_params(summarize(mesh, p.boundary.rule == BoundaryRule::curve), p);
}

Mesh honeycomb(const Mesh& mesh, const HoneycombParams& p, Origins* origins) {
  const FaceSummary s = summarize(mesh, p.boundary.rule == BoundaryRule::curve);
  check_params(s, p);

  const std::size_t max_n = s.max_size;
  std::vector<glm::dvec3> edge_points(max_n);
  std::vector<double> cosines(max_n > direct_max ? max_n : 0), sines(cosines.size());
  WeightTable table(p);
  const double t = p.t;

  const auto face_points = [&](FaceId, std::span<const CornerId> corners, std::span<glm::dvec3> new_points) {
    const auto N = std::uint32_t(corners.size());
    // Work relative to v_0: the weights sum to 1, and small differences keep precision far from the origin.
    const glm::dvec3 origin = mesh.position(mesh.vertex(corners[0]));
    glm::dvec3 d_first(0.0), d = d_first;
    for (std::uint32_t i = 0; i < N; ++i) {
      const glm::dvec3 d_next =
          i + 1 < N ? mesh.position(mesh.vertex(corners[i + 1])) - origin : d_first;  // v_{i+1} - v_0
      edge_points[i] = (1.0 - t) * d + t * d_next;  // formula (1): the point on edge e_i
      d = d_next;
    }
    if (N <= direct_max) {
      // Formula (2) is circulant: a_{n,m} depends on n - m mod N only.
      const double* w = table.row(N);
      for (std::uint32_t n = 0; n < N; ++n) {
        glm::dvec3 sum(0.0);
        for (std::uint32_t m = 0; m < N; ++m) sum += w[n >= m ? n - m : n + N - m] * edge_points[m];
        new_points[n] = origin + sum;
      }
      return;
    }
    // sum_{m != n} (3 + 2 cos(theta (n - m))) p_m = 3 P + 2 (cos(theta n) Cs + sin(theta n) Sn) - 5 p_n,
    // with P = sum p_m, Cs = sum cos(theta m) p_m, Sn = sum sin(theta m) p_m, theta = 2 pi / N.
    const double a = honeycomb_tension(p, int(N));
    const double scale = (1.0 - a) / (3.0 * double(N) - 5.0);
    glm::dvec3 total(0.0), cos_sum(0.0), sin_sum(0.0);
    for (std::uint32_t m = 0; m < N; ++m) {
      const double angle = 2.0 * std::numbers::pi * double(m) / double(N);
      cosines[m] = std::cos(angle);
      sines[m] = std::sin(angle);
      total += edge_points[m];
      cos_sum += cosines[m] * edge_points[m];
      sin_sum += sines[m] * edge_points[m];
    }
    for (std::uint32_t n = 0; n < N; ++n) {
      const glm::dvec3 rest =
          3.0 * total + 2.0 * (cosines[n] * cos_sum + sines[n] * sin_sum) - 5.0 * edge_points[n];
      new_points[n] = origin + (a * edge_points[n] + scale * rest);
    }
  };
  Mesh result = detail::honeycomb_remesh(mesh, face_points, false, p.boundary, "honeycomb", origins).mesh;
  if (p.planarize && detail::lateral_rule_applies(mesh)) detail::planarize_new_faces(result);
  return result;
}

namespace detail {

std::vector<ParamSpec> honeycomb_param_specs() {
  const HoneycombParams d;
  return with_boundary_params({
      param("t", ParamType::number, d.t, "where each edge's point lies: (1 - t) v_m + t v_m+1, formula (1)")
          .in(0, 1),
      param("a", ParamType::number, "a constant tension for every face, in place of a0 + a1/N")
          .optional("a0 + a1/N for an N-sided face")
          .in_open(0, 1),
      param("a0", ParamType::number, d.a0, "the tension a0 + a1/N of an N-sided face: its constant part"),
      param("a1", ParamType::number, d.a1, "the tension a0 + a1/N of an N-sided face: the part divided by N"),
  });
}

std::vector<ParamSpec> with_planarize_param(std::vector<ParamSpec> specs) {
  specs.push_back(param("planarize", ParamType::integer, 0,
                        "1: planarize the new faces of the step from a control mesh with a flat region when "
                        "that bends no more than the plain step, against lateral artifacts "
                        "(docs/lateral_artifacts.md); 0: the plain step")
                      .in(0, 1));
  return specs;
}

void check_honeycomb_param_set(const std::string& scheme, const Params& given, Params& resolved) {
  if (!resolved.has("a")) return;
  const auto given_value = [&](const char* name) { return given.has(name) && !given.get(name).empty(); };
  if (given_value("a0") || given_value("a1")) {
    throw ParameterError(
        scheme + ": give either parameter a (constant tension) or a0/a1 (a = a0 + a1/N), not both", "a");
  }
  resolved.erase("a0");
  resolved.erase("a1");
}

HoneycombParams honeycomb_params_from(const Params& p) {
  HoneycombParams h;
  h.t = p.number("t");
  if (p.has("a")) h.a = p.number("a");
  if (p.has("a0")) h.a0 = p.number("a0");
  if (p.has("a1")) h.a1 = p.number("a1");
  h.boundary = boundary_options_from(p);
  h.planarize = p.has("planarize") && p.integer("planarize") == 1;
  return h;
}

SchemeSpec honeycomb_scheme() {
  return {
      "honeycomb",
      "Akleman-Srinivasan honeycomb: a shrunken copy of every face and a face around every old vertex",
      with_planarize_param(honeycomb_param_specs()),
      [](const Params& given, Params& resolved) { check_honeycomb_param_set("honeycomb", given, resolved); },
      [](const Mesh& m, const Params& p, Origins* origins) {
        return honeycomb(m, honeycomb_params_from(p), origins);
      },
      [](const MeshCounts& c, const Params&) { return honeycomb_counts(c); }};
}

}  // namespace detail
}  // namespace dlfl

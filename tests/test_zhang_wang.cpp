// Zhang-Wang honeycomb subdivision with central control vertices: the honeycomb's counts and topology, the
// formulas (2) to (4) against hand-derived values, the subdivision matrix (6) and its eigenvalues (9) read
// off the code by applying it to unit vectors, the limit point (15) against many iterations, the bounds of
// (12), affine invariance, parameters, and the control points through JSON, the editor and the log.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/io/json_mesh.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include <dlfl/statistics.h>
#include <dlfl/validate.h>
#include "honeycomb_checks.h"
#include "log_helpers.h"
#include "scheme_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

using test::Histogram;
using Matrix = std::vector<std::vector<double>>;

bool close(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-12) {
  return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

glm::dvec3 centroid(const Mesh& m, FaceId f) {
  glm::dvec3 s(0.0);
  for (CornerId c : m.corners(f)) s += m.position(m.vertex(c));
  return s / double(m.size(f));
}

// The face of a step's output that stems from `source`: each input face and vertex has exactly one.
FaceId face_from(const Origins& origins, const Origin& source) {
  FaceId found;
  for (std::uint32_t f = 0; f < origins.faces.size(); ++f) {
    if (origins.faces[f] != source) continue;
    REQUIRE_FALSE(found.valid());
    found = FaceId(f);
  }
  REQUIRE(found.valid());
  return found;
}

// One step checked against the honeycomb's closed forms, every face with a CCV.
Mesh checked_step(const Mesh& m, const ZhangWangParams& p = {}) {
  Mesh r = test::checked_honeycomb_step(m, [&](const Mesh& in) { return zhang_wang_honeycomb(in, p); });
  for (FaceId f : r.faces()) CHECK(face_point(r, f).has_value());
  return r;
}

// A face manifold (a two-sided polygon) of the given points, its front face with control point q.
Mesh face_manifold(const std::vector<glm::dvec3>& points, const glm::dvec3& q, FaceId* front) {
  Mesh m;
  const FaceManifold fm = create_face_manifold(m, points);
  set_face_point(m, fm.front, q);
  *front = fm.front;
  return m;
}

// The front face's control points after one step, as [q', p'_0 .. p'_{n-1}] (p'_i from the copy's first
// corner on): what the matrix S of formula (6) maps [q, p_0 .. p_{n-1}] to.
std::vector<glm::dvec3> step_face(const std::vector<glm::dvec3>& points, const glm::dvec3& q,
                                  const ZhangWangParams& p) {
  FaceId front;
  const Mesh m = face_manifold(points, q, &front);
  Origins origins;
  const Mesh r = zhang_wang_honeycomb(m, p, &origins);
  const FaceId copy = face_from(origins, origin_of(front));
  std::vector<glm::dvec3> out{*face_point(r, copy)};
  for (CornerId c : r.corners(copy)) out.push_back(r.position(r.vertex(c)));
  return out;
}

// S of one n-gon, column j = the x coordinates the code gives for unit vector j (control j at x = 1, the
// others at x = 0; y and z put the points on a circle and play no part in x).
Matrix code_matrix(int n, const ZhangWangParams& p) {
  Matrix S(n + 1, std::vector<double>(n + 1));
  for (int j = 0; j <= n; ++j) {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * i / n;
      points.push_back({j == i + 1 ? 1.0 : 0.0, std::cos(angle), std::sin(angle)});
    }
    const auto out = step_face(points, {j == 0 ? 1.0 : 0.0, 0.0, 0.0}, p);
    for (int i = 0; i <= n; ++i) S[i][j] = out[i].x;
  }
  return S;
}

Matrix multiply(const Matrix& A, const Matrix& B) {
  Matrix C(A.size(), std::vector<double>(B[0].size(), 0.0));
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t k = 0; k < B.size(); ++k)
      for (std::size_t j = 0; j < B[0].size(); ++j) C[i][j] += A[i][k] * B[k][j];
  return C;
}

std::vector<double> times(const Matrix& A, const std::vector<double>& x) {
  std::vector<double> y(A.size(), 0.0);
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j) y[i] += A[i][j] * x[j];
  return y;
}

// S~ = R S S of formula (8): two steps, with the rows of the points turned back by one so that row i
// again belongs to the point near p_i (after two steps the point of corner i sits near p_{i+1}).
Matrix double_step(const Matrix& S) {
  const Matrix SS = multiply(S, S);
  const std::size_t n = S.size() - 1;
  Matrix out = SS;
  for (std::size_t i = 0; i < n; ++i) out[1 + i] = SS[1 + (i + n - 1) % n];
  return out;
}

}  // namespace

TEST_CASE("zhang-wang: counts valences face sizes and topology on closed meshes") {
  checked_step(test::tetrahedron());
  checked_step(test::cube());
  checked_step(test::dodecahedron());
  checked_step(build_mesh(test::torus_soup(6, 5)));
  checked_step(build_mesh(test::genus_soup(2)));
  checked_step(checked_step(test::mixed_polyhedron()));
}

TEST_CASE("zhang-wang: the cube by hand") {
  // Cube [-1, 1]^3, CCVs = face centres. On the face z = 1 (q = (0, 0, 1)) the edge from (1, 1, 1) to
  // (-1, 1, 1) has midpoint (0, 1, 1), so p' = q/3 + 2/3 (0, 1, 1) = (0, 2/3, 1): every new vertex is a
  // point with one coordinate +-1, one +-2/3 and one 0 (24 of them, each once). A face's copy keeps the
  // CCV q' = (1 - a) q + a p_bar = q since q = p_bar. The vertex (1, 1, 1) has neighbours summing to
  // (1, 1, 1) and face CCVs summing to (1, 1, 1); formula (4) with c = 1/2 and weights 1/6 gives
  // (1, 1, 1)/2 + (1/6 (1, 1, 1) + 1/6 (1, 1, 1))/2 = 2/3 (1, 1, 1).
  const Mesh r = checked_step(test::cube());
  std::vector<glm::dvec3> expected;
  for (int axis = 0; axis < 3; ++axis)
    for (int other = 0; other < 3; ++other) {
      if (other == axis) continue;
      for (double s : {-1.0, 1.0})
        for (double t : {-2.0 / 3, 2.0 / 3}) {
          glm::dvec3 p(0.0);
          p[axis] = s;
          p[other] = t;
          expected.push_back(p);
        }
    }
  REQUIRE(expected.size() == 24);
  for (const auto& e : expected) {
    int found = 0;
    for (VertexId v : r.vertices()) found += close(r.position(v), e);
    CHECK(found == 1);
  }
  for (FaceId f : r.faces()) {
    const glm::dvec3 q = *face_point(r, f);
    CAPTURE(f.index());
    if (r.size(f) == 4) {
      CHECK(close(q, centroid(r, f)));
      CHECK(std::abs(std::abs(q.x) + std::abs(q.y) + std::abs(q.z) - 1.0) < 1e-12);  // a face centre
    } else {
      REQUIRE(r.size(f) == 6);
      for (int k = 0; k < 3; ++k) CHECK(std::abs(std::abs(q[k]) - 2.0 / 3) < 1e-12);
    }
  }
}

TEST_CASE("zhang-wang: a raised control point pulls its face as formulas (2) and (3) say") {
  // The cube's face z = 1 (first corner where the soup starts it) with q = (0, 0, 2): its edge points move
  // by (1 - b) (0, 0, 1) = (0, 0, 1/3), so the edge with midpoint (0, 1, 1) gives (0, 2/3, 4/3); the copy's
  // CCV is (1 - a_4) (0, 0, 2) + a_4 (0, 0, 1) with a_4 = (4 - cos(pi/2)) / 9 = 4/9: z = 2 - 4/9 = 14/9.
  Mesh m = test::cube();
  FaceId top;
  for (FaceId f : m.faces())
    if (close(centroid(m, f), {0, 0, 1})) top = f;
  REQUIRE(top.valid());
  set_face_point(m, top, glm::dvec3(0, 0, 2));
  Origins origins;
  const Mesh r = zhang_wang_honeycomb(m, {}, &origins);
  const FaceId copy = face_from(origins, origin_of(top));
  CHECK(close(*face_point(r, copy), {0, 0, 14.0 / 9}));
  int raised = 0;
  for (CornerId c : r.corners(copy)) {
    const glm::dvec3 p = r.position(r.vertex(c));
    CHECK(std::abs(p.z - 4.0 / 3) < 1e-12);
    raised += close(p, {0, 2.0 / 3, 4.0 / 3});
  }
  CHECK(raised == 1);
  // The vertex (1, 1, 1) sees the raised CCV among its faces: the sum of CCVs becomes (1, 1, 2), so its
  // face's CCV is (1, 1, 1)/2 + ((1, 1, 1) + (1, 1, 2))/12 = (2/3, 2/3, 3/4).
  for (VertexId v : m.vertices()) {
    if (!close(m.position(v), {1, 1, 1})) continue;
    CHECK(close(*face_point(r, face_from(origins, origin_of(v))), {2.0 / 3, 2.0 / 3, 0.75}));
  }
}

TEST_CASE("zhang-wang: alpha splits formula (4) between the neighbours and the face CCVs") {
  // The cube's vertex (1, 1, 1) with the top face's CCV raised to (0, 0, 2): neighbours sum to (1, 1, 1),
  // face CCVs to (1, 1, 2). alpha = 1: (1, 1, 1)/2 + (1, 1, 1)/6 = 2/3 (1, 1, 1); alpha = 0:
  // (1, 1, 1)/2 + (1, 1, 2)/6 = (2/3, 2/3, 5/6).
  Mesh m = test::cube();
  for (FaceId f : m.faces())
    if (close(centroid(m, f), {0, 0, 1})) set_face_point(m, f, glm::dvec3(0, 0, 2));
  for (const auto& [alpha, expected] : std::vector<std::pair<double, glm::dvec3>>{
           {1.0, {2.0 / 3, 2.0 / 3, 2.0 / 3}}, {0.0, {2.0 / 3, 2.0 / 3, 5.0 / 6}}}) {
    ZhangWangParams p;
    p.alpha = alpha;
    Origins origins;
    const Mesh r = zhang_wang_honeycomb(m, p, &origins);
    for (VertexId v : m.vertices())
      if (close(m.position(v), {1, 1, 1}))
        CHECK(close(*face_point(r, face_from(origins, origin_of(v))), expected));
  }
}

TEST_CASE("zhang-wang: c = 0 keeps the vertex faces' CCVs on the old vertices") {
  ZhangWangParams p;
  p.c = 0;
  const Mesh m = test::dodecahedron();
  Origins origins;
  const Mesh r = zhang_wang_honeycomb(m, p, &origins);
  for (VertexId v : m.vertices()) CHECK(*face_point(r, face_from(origins, origin_of(v))) == m.position(v));
}

TEST_CASE("zhang-wang: the matrix of formula (6) read off the code") {
  for (int n = 3; n <= 8; ++n) {
    ZhangWangParams p;
    const double a = zhang_wang_a(p, n), b = p.b;
    const Matrix S = code_matrix(n, p);
    CAPTURE(n);
    // Row 0: q' = (1 - a) q + a/n sum p_i. Row 1 + i: p'_i = (1 - b) q + b/2 (p_i + p_{i+1}).
    CHECK(S[0][0] == doctest::Approx(1 - a).epsilon(1e-14));
    for (int j = 1; j <= n; ++j) CHECK(S[0][j] == doctest::Approx(a / n).epsilon(1e-14));
    for (int i = 0; i < n; ++i) {
      CHECK(S[1 + i][0] == doctest::Approx(1 - b).epsilon(1e-14));
      for (int j = 0; j < n; ++j) {
        const double expected = (j == i || j == (i + 1) % n) ? b / 2 : 0.0;
        CHECK(std::abs(S[1 + i][1 + j] - expected) < 1e-14);
      }
    }
  }
}

TEST_CASE("zhang-wang: the double step matrix has the eigenvalues of formula (9)") {
  // Eigenvalues of S~ = R S S: 1 and (a - b)^2 on the span of q and the sum of the points, and
  // b^2 (1 + cos(2 pi k / n)) / 2 for k = 1 .. n-1 on the Fourier vectors of the points (whose sum is 0, so
  // q's row does not see them). Together that is all n + 1 eigenvalues.
  for (int n = 3; n <= 9; ++n) {
    for (const auto& given : std::vector<std::pair<double, double>>{{-1, 2.0 / 3}, {0.3, 0.5}, {0.9, 0.8}}) {
      const double a_given = given.first, b = given.second;  // not bindings: clang 14 cannot capture them
      ZhangWangParams p;
      p.b = b;
      if (a_given >= 0) p.a = a_given;
      const double a = zhang_wang_a(p, n);
      const Matrix T = double_step(code_matrix(n, p));
      CAPTURE(n);
      CAPTURE(a);
      CAPTURE(b);
      for (int k = 1; k < n; ++k) {
        const double lambda = b * b * (1 + std::cos(2 * std::numbers::pi * k / n)) / 2;
        for (int phase = 0; phase < 2; ++phase) {  // the cosine and the sine vector
          std::vector<double> x(n + 1, 0.0);
          for (int i = 0; i < n; ++i) {
            const double angle = 2 * std::numbers::pi * k * i / n;
            x[1 + i] = phase == 0 ? std::cos(angle) : std::sin(angle);
          }
          const auto y = times(T, x);
          for (int i = 0; i <= n; ++i) CHECK(std::abs(y[i] - lambda * x[i]) < 1e-13);
        }
      }
      // The span of e_q = (1, 0 .. 0) and e_p = (0, 1 .. 1) is invariant: T e = alpha e_q + beta e_p.
      std::vector<double> eq(n + 1, 0.0), ep(n + 1, 1.0);
      eq[0] = 1;
      ep[0] = 0;
      const auto yq = times(T, eq), yp = times(T, ep);
      for (int i = 2; i <= n; ++i) {
        CHECK(std::abs(yq[i] - yq[1]) < 1e-14);
        CHECK(std::abs(yp[i] - yp[1]) < 1e-14);
      }
      // The 2x2 block [[yq0, yp0], [yq1, yp1]]: eigenvalues 1 and (a - b)^2 <=> trace 1 + (a - b)^2 and
      // determinant (a - b)^2.
      const double trace = yq[0] + yp[1], det = yq[0] * yp[1] - yp[0] * yq[1];
      CHECK(trace == doctest::Approx(1 + (a - b) * (a - b)).epsilon(1e-13));
      CHECK(det == doctest::Approx((a - b) * (a - b)).epsilon(1e-12));
    }
  }
}

TEST_CASE("zhang-wang: the limit point of formula (15) agrees with many iterations") {
  // A face's copy depends on the face alone (the paper's section 3.1), so iterating a lone two-sided polygon,
  // rebuilt from its front face's copy after each step, follows one face down to its limit point.
  const std::vector<glm::dvec3> start{{0, 0, 0}, {2, 0, 0.3}, {3, 1, -0.2}, {1.5, 2.5, 0.4}, {-1, 1, 0.1}};
  const glm::dvec3 bump(0.7, 1.4, 2.0);  // far from the centroid (0.7, 0.9, 0.12)
  for (const ZhangWangParams& p : {ZhangWangParams{}, ZhangWangParams{0.35, 0.5, 0.5, 0.5}}) {
    FaceId front;
    const Mesh m0 = face_manifold(start, bump, &front);
    const glm::dvec3 limit = zhang_wang_limit_point(m0, front, p);
    std::vector<glm::dvec3> points = start;
    glm::dvec3 q = bump;
    for (int step = 0; step < 60; ++step) {
      const auto out = step_face(points, q, p);
      q = out[0];
      points.assign(out.begin() + 1, out.end());
    }
    CHECK(close(q, limit, 1e-9));
    for (const auto& x : points) CHECK(close(x, limit, 1e-9));
    // The limit is not the centroid: the bump matters.
    CHECK_FALSE(close(limit, centroid(m0, front), 1e-3));
  }
}

TEST_CASE("zhang-wang: the parameter bounds of formula (12) and of the eigenvalues") {
  // n = 3: phi/2 = pi/3, cos = 1/2, so (12) gives (1/3 b, b) and the eigen bounds (b/2, 3b/2).
  const TensionBounds t3 = zhang_wang_paper_bounds(3, 2.0 / 3);
  CHECK(t3.lower == doctest::Approx(2.0 / 9));
  CHECK(t3.upper == doctest::Approx(2.0 / 3));
  // n = 4: cos(pi/4) = sqrt(2)/2, so c/(1+c) = sqrt(2) - 1 and c/(1-c) = sqrt(2) + 1.
  const TensionBounds t4 = zhang_wang_paper_bounds(4, 0.6);
  CHECK(t4.lower == doctest::Approx((std::sqrt(2.0) - 1) * 0.6));
  CHECK(t4.upper == doctest::Approx((std::sqrt(2.0) + 1) * 0.6));
  const TensionBounds e3 = zhang_wang_eigen_bounds(3, 2.0 / 3);
  CHECK(e3.lower == doctest::Approx(1.0 / 3));
  CHECK(e3.upper == doctest::Approx(1.0));
  // The symmetric default a_n lies inside both for every n.
  for (int n = 3; n <= 40; ++n) {
    const double a = zhang_wang_a({}, n);
    CAPTURE(n);
    CHECK(zhang_wang_paper_bounds(n, 2.0 / 3).lower < a);
    CHECK(a < zhang_wang_paper_bounds(n, 2.0 / 3).upper);
    CHECK(zhang_wang_eigen_bounds(n, 2.0 / 3).lower < a);
    CHECK(a < zhang_wang_eigen_bounds(n, 2.0 / 3).upper);
  }
  // The eigen bounds are where (a - b)^2, read off the code's double step, meets the subdominant eigenvalue.
  for (int n : {3, 5, 8}) {
    const double b = 0.6;
    const TensionBounds e = zhang_wang_eigen_bounds(n, b);
    const double subdominant = b * b * (1 + std::cos(2 * std::numbers::pi / n)) / 2;
    for (const auto& sample : std::vector<std::pair<double, bool>>{
             {e.lower + 1e-3, true}, {e.lower - 1e-3, false}, {e.upper - 1e-3, true}}) {
      const double a = sample.first;  // not a binding: clang 14 cannot capture one in CAPTURE's lambda
      const bool inside = sample.second;
      if (a < 0 || a > 1) continue;
      ZhangWangParams p;
      p.a = a;
      p.b = b;
      const Matrix T = double_step(code_matrix(n, p));
      std::vector<double> eq(n + 1, 0.0), ep(n + 1, 1.0);
      eq[0] = 1;
      ep[0] = 0;
      const auto yq = times(T, eq), yp = times(T, ep);
      const double det = yq[0] * yp[1] - yp[0] * yq[1];  // the eigenvalue (a - b)^2, the other one being 1
      CAPTURE(n);
      CAPTURE(a);
      CHECK((det < subdominant) == inside);
    }
  }
  CHECK_THROWS_AS(zhang_wang_paper_bounds(2, 0.5), InvalidArgument);
  CHECK_THROWS_AS(zhang_wang_eigen_bounds(5, 1.5), InvalidArgument);
}

TEST_CASE("zhang-wang: affine maps commute with the subdivision") {
  Mesh m = test::mixed_polyhedron();
  FaceId some = *m.faces().begin();
  set_face_point(m, some, glm::dvec3(0.3, -2, 1.5));
  const auto map = [](const glm::dvec3& p) {
    return glm::dvec3(2 * p.x - p.y + 3, 0.5 * p.y + p.z - 1, -p.x + 1.5 * p.z + 0.25);
  };
  Mesh mapped = m;
  for (VertexId v : m.vertices()) mapped.set_position(v, map(m.position(v)));
  for (FaceId f : m.faces())
    if (auto q = face_point(m, f)) set_face_point(mapped, f, map(*q));
  const Mesh r = zhang_wang_honeycomb(m), rm = zhang_wang_honeycomb(mapped);
  REQUIRE(r.vertex_capacity() == rm.vertex_capacity());
  for (VertexId v : r.vertices()) CHECK(close(map(r.position(v)), rm.position(v), 1e-11));
  for (FaceId f : r.faces()) CHECK(close(map(*face_point(r, f)), *face_point(rm, f), 1e-11));
}

TEST_CASE("zhang-wang: hole faces stay holes and point spheres are copied") {
  // The grid's hole of 10 corners: under boundary=hole a hole of 10 again, under curve (formula (15)) of 20.
  Mesh grid = build_mesh(test::grid_soup(3, 2));
  for (const BoundaryRule rule : {BoundaryRule::curve, BoundaryRule::hole}) {
    ZhangWangParams p;
    p.boundary.rule = rule;
    const Mesh r = zhang_wang_honeycomb(grid, p);
    require_valid(r);
    std::vector<std::uint32_t> holes;
    for (FaceId f : r.faces()) {
      if (r.is_hole(f)) holes.push_back(r.size(f));
    }
    CHECK(holes == std::vector<std::uint32_t>{rule == BoundaryRule::curve ? 20u : 10u});
  }
  Mesh with_point = test::cube();
  with_point.create_vertex({5, 5, 5});
  const Mesh rp = zhang_wang_honeycomb(with_point);
  require_valid(rp);
  CHECK(statistics(rp).point_spheres == 1);
}

TEST_CASE("zhang-wang: bad parameters are refused naming them") {
  const Mesh m = test::cube();
  for (const auto& bad : std::vector<std::pair<const char*, double>>{
           {"a", 1.5}, {"b", -0.1}, {"c", 2}, {"alpha", std::nan("")}}) {
    const char* name = bad.first;  // not a binding: clang 14 cannot capture one in CAPTURE's lambda
    const double value = bad.second;
    CAPTURE(name);
    try {
      apply_scheme(m, "honeycomb-zw", resolve_scheme_params("honeycomb-zw", {{name, value}}));
      FAIL("accepted");
    } catch (const InvalidArgument& e) {
      CHECK(std::string(e.what()).find(std::string("parameter ") + name) != std::string::npos);
    }
  }
  CHECK_THROWS_AS(resolve_scheme_params("honeycomb-zw", {{"a", std::string("steep")}}), InvalidArgument);
  CHECK_THROWS_AS(resolve_scheme_params("honeycomb-zw", {{"d", 0.5}}), InvalidArgument);
  const Params full = resolve_scheme_params("honeycomb-zw", {});
  CHECK(full.text("a") == "symmetric");
  CHECK(full.number("b") == 2.0 / 3);
  CHECK(full.number("c") == 0.5);
  CHECK(full.number("alpha") == 0.5);
  // The keyword and a number both resolve for `a`; a number of an old log (a double) stays a number.
  CHECK(resolve_scheme_params("honeycomb-zw", {{"a", "symmetric"}}).text("a") == "symmetric");
  CHECK(resolve_scheme_params("honeycomb-zw", {{"a", "0.4"}}).number("a") == 0.4);
  FaceId front;
  Mesh fm = face_manifold({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 0, 1}, &front);
  ZhangWangParams stuck;
  stuck.a = 0;
  stuck.b = 1;
  CHECK_THROWS_AS(zhang_wang_limit_point(fm, front, stuck), InvalidArgument);
  CHECK_THROWS_AS(set_face_point(fm, front, glm::dvec3(std::nan(""), 0, 0)), InvalidArgument);
}

TEST_CASE("face points: JSON round trip and hash") {
  Mesh m = test::cube();
  const std::string plain = mesh_hash(m);
  const FaceId f = *m.faces().begin();
  set_face_point(m, f, glm::dvec3(0.1, 0.2, 0.3));
  CHECK(mesh_hash(m) != plain);
  const Mesh back = mesh_from_json(mesh_to_json(m), "test");
  CHECK(back == m);
  CHECK(*face_point(back, f) == glm::dvec3(0.1, 0.2, 0.3));
  CHECK(mesh_hash(back) == mesh_hash(m));
  set_face_point(m, f, std::nullopt);
  CHECK_FALSE(face_point(m, f).has_value());
  CHECK(mesh_hash(m) == plain);    // unset points are not hashed, as before they were attributes
  CHECK_FALSE(m == test::cube());  // but the attribute is there, all NaN
  m.remove_face_attribute(face_point_attribute);
  CHECK(m == test::cube());
  // A subdivided mesh with a CCV on every face survives the round trip exactly.
  const Mesh r = zhang_wang_honeycomb(test::dodecahedron());
  CHECK(mesh_from_json(mesh_to_json(r), "test") == r);
  // A malformed entry is refused, naming the field.
  auto doc = mesh_to_json(r);
  REQUIRE(doc["attributes"].size() == 1);
  CHECK(doc["attributes"][0]["name"] == "face_point");
  doc["attributes"][0]["values"][0] = "up";
  CHECK_THROWS_WITH_AS(mesh_from_json(doc, "bad"), doctest::Contains("attributes[0].values[0]"), IoError);
}

TEST_CASE("face points: set by the editor undo and redo and replay from the log") {
  Editor ed;
  ed.set_mesh(test::cube());
  const FaceId f = *ed.mesh().faces().begin();
  ed.set_face_point(f, glm::dvec3(0, 0, 3));
  ed.subdivide("honeycomb-zw");
  const Mesh after = ed.mesh();
  CHECK(ed.undo());
  CHECK(*face_point(ed.mesh(), f) == glm::dvec3(0, 0, 3));
  CHECK(ed.undo());
  CHECK_FALSE(face_point(ed.mesh(), f).has_value());
  CHECK(ed.redo());
  CHECK(ed.redo());
  CHECK(ed.mesh() == after);
  ed.set_face_point(*ed.mesh().faces().begin(), std::nullopt);
  const Editor again = replay_log(log_text(ed));
  CHECK(again.mesh() == ed.mesh());
  CHECK(mesh_hash(again.mesh()) == mesh_hash(ed.mesh()));
  CHECK_THROWS_AS(ed.set_face_point(FaceId(999999), glm::dvec3(0.0)), InvalidArgument);
}

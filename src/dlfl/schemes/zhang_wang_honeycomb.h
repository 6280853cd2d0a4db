#pragma once
// Zhang and Wang's honeycomb subdivision with central control vertices ("Honeycomb subdivision", Journal of
// Software 2002): the honeycomb's topology (dlfl/schemes/honeycomb.h) with every face carrying a central
// control vertex (CCV), stored as the face's control point: the point face attribute "face_point"
// (`face_point`, `set_face_point` below; NaN means unset). A face without one uses its centroid (the
// barycenter of its vertices), which is also what a loaded mesh starts with.
//
// One step, for a face P = [q; p_1 .. p_n] (q its CCV, p_i its vertices in order):
//   new edge vertex  p'_i = (1 - b_n) q + b_n (p_i + p_{i+1}) / 2                       formula (2)
//   new face's CCV   q'   = (1 - a_n) q + a_n p_bar,  p_bar = (p_1 + .. + p_n) / n        formula (3)
// and for an old vertex v of valence n, with neighbours p_i and the CCVs q_i of the faces around it, the new
// face around v gets the CCV
//   q~ = (1 - c_n) v + c_n (sum alpha_i p_i + sum beta_i q_i)                            formula (4)
// with alpha_i = alpha / n and beta_i = (1 - alpha) / n, so that sum (alpha_i + beta_i) = 1 as the paper
// requires (alpha = 1/2 gives the alpha_i = beta_i = 1/(2n)).
//
// Open meshes (the paper's section 4.2, "Boundaries"), by ZhangWangParams::boundary.rule:
// - `curve` (the default): the paper's boundary rule. A boundary vertex v, between its boundary neighbours
//   v_1 and v_2, adds a new edge vertex to its new vertex face, at
//     v_b = (1 - s_n) v + s_n (v_1 + v_2) / 2                                             formula (15)
//   and a boundary edge's new edge vertex on the hole's side is its midpoint (formula (2) with the edge's own
//   midpoint in place of a CCV, which a hole has not), joined across the edge to the face's edge vertex as
//   every edge is. Weight: s_n = 1/2 for every n. Reasons (docs/zhang_wang.md, docs/boundaries.md):
//   (a) a weight that depended on the valence n would let the faces inside change the boundary curve, so
//       two meshes sharing a boundary loop would crack apart;
//   (b) the paper adds v_b only at vertices of valence greater than 2, and we keep a vertex of valence 2 in
//       place (a corner); after one step every other boundary vertex is a v_b of valence 2, and s_n = 1/2 is
//       the only constant weight for which such a vertex already lies where (15) would put it (the midpoint
//       of its neighbours), so keeping it and smoothing it agree and the rule is the same at every step;
//   (c) the boundary then depends on the boundary polygon alone, and its limit is the uniform quadratic
//       B-spline whose control polygon is the polygon of the boundary edges' midpoints: a C1 curve through
//       (v_1 + 2v + v_2)/4 at every boundary vertex, the v_b of the first step, which never moves again.
//   It is the rule `honeycomb` derives from its vertex insertion and corner cutting, so both honeycombs have
//   the same boundary curve. A boundary vertex with exactly two edges is a corner (`sharp_corners`, the
//   default) and keeps its place, v_b = v, as the paper's "valence greater than 2" asks; so does a vertex
//   marked `sharp`, whose v_b is marked `sharp` in the result. Between sharp vertices the limit is the
//   clamped quadratic B-spline of (v, midpoints, ..., next sharp vertex). A hole has no CCV: the vertex
//   face's CCV of a boundary vertex (formula (4)) spreads 1 - alpha over the faces it has, and the hole's
//   shrunken copy (still a hole, of 2N corners for N) gets no CCV. Counts: with H hole corners,
//   V' = 2E + H, E' = 3E + H, F' = F + V.
// - `hole` (the behaviour before boundary rules): hole faces are treated as faces (their CCV is their
//   centroid unless set), and the shrunken copy of a hole is flagged as a hole again, as in `honeycomb`.
// Point spheres are copied through unchanged, without a CCV.

#include <optional>
#include <string_view>

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// The name of the face attribute (of type point) that holds the control points. Unset points are NaN, the
/// attribute's default.
inline constexpr std::string_view face_point_attribute = "face_point";

/// The value of the "face_point" attribute on a face without a control point (its default): NaN, NaN, NaN.
glm::dvec3 unset_face_point();

/// The face's control point, if one is set (a point with a NaN component counts as unset). Throws
/// InvalidArgument for a removed face, or if the mesh has a "face_point" face attribute of another type.
std::optional<glm::dvec3> face_point(const Mesh& mesh, FaceId f);

/// The control point if set, else the centroid of the face's vertices. Throws as `face_point`.
glm::dvec3 face_point_or_centroid(const Mesh& mesh, FaceId f);

/// Sets a face's control point, or with `std::nullopt` unsets it (stores NaN). The first point set creates
/// the attribute (default NaN); unsetting on a mesh without it changes nothing. A removed face keeps its
/// point, so bringing the face back restores it. Throws InvalidArgument for a removed face, a non-finite
/// point, or a "face_point" face attribute of another type.
void set_face_point(Mesh& mesh, FaceId f, const std::optional<glm::dvec3>& point);

/// The weights of formulas (2), (3) and (4). Every weight must lie in [0, 1].
struct ZhangWangParams {
  /// a_n of formula (3). Unset: the paper's symmetric choice a_n = (4 - cos(2 pi / n)) / 9.
  std::optional<double> a;
  /// b_n of formula (2); the default 2/3 makes p'_i the centroid of the triangle (q, p_i, p_{i+1}).
  double b = 2.0 / 3.0;
  /// c_n of formula (4): 0 puts the new face's CCV on the old vertex, 1 on the average of its neighbourhood.
  double c = 0.5;
  /// The total weight of the neighbours p_i in formula (4) (n alpha_i); the CCVs q_i get 1 - alpha.
  double alpha = 0.5;
  /// What the step does at the boundary loops of an open mesh (see above); the default is formula (15).
  BoundaryOptions boundary = {};
  /// The lateral rule against the bricklayers' problem (docs/lateral_artifacts.md): when the input is a
  /// control mesh (an inner vertex whose valence is not 3) with a flat region (two neighbouring faces in one
  /// plane), the step's new faces are planarized, kept only if that makes no more concave edges and no
  /// larger mean dihedral angle than the plain step, and then each face's CCV is put on its plane (vertices
  /// moved, the counts, 3-valence and topology unchanged; vertices on a hole stay). Off by default: off, or
  /// otherwise, the plain step, bit for bit.
  bool planarize = false;
};

/// a_n for a face of n vertices: `p.a` when set, else (4 - cos(2 pi / n)) / 9. Throws InvalidArgument for
/// n < 2.
double zhang_wang_a(const ZhangWangParams& p, int n);

/// Throws InvalidArgument naming the parameter if a weight is outside [0, 1] (or NaN).
void check_zhang_wang_params(const ZhangWangParams& p);

/// One step. The input is not modified. The result has the honeycomb's topology (V' = 2E, E' = 3E,
/// F' = F + V, every new vertex 3-valent, each shrunken face of its old face's size, each vertex face of
/// twice its old vertex's valence, the Euler characteristic and genus of every component kept; under the
/// boundary rule, see above), and every face of it (point spheres and, under `curve`, holes aside) carries
/// its CCV. Handles are those of `honeycomb` on the same mesh with the same boundary options. The result has
/// no attribute but "face_point" (and "sharp" when the boundary rule keeps a marked vertex).
/// The shrunken copy of a face starts at the point for the face's first corner (the point on the edge leaving
/// it). Throws InvalidArgument for a bad parameter or a non-finite new point. When `origins` is given it
/// receives the origin of every element, those of `honeycomb` (dlfl/schemes/honeycomb.h): the shrunken copy
/// of a face stems from that face, the new face around a vertex from that vertex, which tracks a face (and
/// its CCV) across levels. It costs nothing when not asked for.
Mesh zhang_wang_honeycomb(const Mesh& mesh, const ZhangWangParams& p = {}, Origins* origins = nullptr);

/// The limit of the centre of face f under repeated steps, formula (15): with q its CCV (or centroid),
/// p_bar its centroid and n its size,
///   (1 - b_n) / (1 + a_n - b_n) q + a_n / (1 + a_n - b_n) p_bar.
/// (The face's shrunken copies depend on the face alone, so this is a property of the face.) Throws
/// InvalidArgument for a removed face, a point sphere, bad parameters, or a_n = 0 with b_n = 1 (then q and
/// p_bar never move, and there is no single limit).
glm::dvec3 zhang_wang_limit_point(const Mesh& mesh, FaceId f, const ZhangWangParams& p = {});

/// An open interval (lower, upper) of the tension a_n.
struct TensionBounds {
  double lower;
  double upper;
};

/// The bounds of formula (12) as the paper prints them, for a face of n sides and a given b_n:
///   cos(phi/2) / (1 + cos(phi/2)) b_n < a_n < cos(phi/2) / (1 - cos(phi/2)) b_n,   phi = 2 pi / n.
/// See docs/zhang_wang.md: these differ from the bounds that formulas (9) and (10) imply, which
/// `zhang_wang_eigen_bounds` gives. Throws InvalidArgument for n < 3 or b_n outside [0, 1].
TensionBounds zhang_wang_paper_bounds(int n, double b);

/// The bounds that make the eigenvalue (a_n - b_n)^2 of formula (9) smaller than the subdominant eigenvalue
/// b_n^2 (1 + cos(2 pi / n)) / 2 = (b_n cos(phi/2))^2, as condition (10) asks:
///   b_n (1 - cos(phi/2)) < a_n < b_n (1 + cos(phi/2)).
/// Throws InvalidArgument for n < 3 or b_n outside [0, 1].
TensionBounds zhang_wang_eigen_bounds(int n, double b);

}  // namespace dlfl

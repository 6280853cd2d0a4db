#pragma once
// Internal to the hulls: orientation predicates whose sign is exact. Each is computed in floating point
// first, with an error bound that decides it in almost every call; only when the result is within the
// bound is it recomputed exactly, as a sum of doubles that is never rounded (the expansion arithmetic of
// Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric predicates").
//
// Exact for finite coordinates of magnitude below 2^500 whose nonzero values are at least 2^-200 times
// the largest (so that no product over- or underflows); the hull scales its points by a power of two, which
// keeps every sign, and takes coordinates below that range as zero.

#include <glm/vec3.hpp>

namespace dlfl::detail {

/// The sign (-1, 0, 1) of det[b - a, c - a, d - a]: positive when d lies on the side of the plane through
/// a, b, c that (b - a) x (c - a) points to, i.e. above the triangle a, b, c turning counter-clockwise.
int orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

/// The same sign, exactly, without the floating-point filter (for callers that have filtered already).
int orient3d_exact(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

/// True if a, b, c lie exactly on one line (or coincide): every coordinate projection of the triangle has
/// zero signed area.
bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

/// The filter of orient3d on differences already rounded as orient3d rounds them (u = b - a, v = c - a,
/// w = d - a, each computed in floating point): the sign of det[u, v, w] when the error bound decides it,
/// 0 when every product in it is exactly 0, and 2 when only the exact computation can tell.
int orient3d_filter(const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w);

/// The relative error bound of the filter: the computed det[u, v, w] of rounded differences is within
/// `orient3d_error_bound` x (|w| . P) of the exact one, P the permanent of the 2 x 2 minors of u and v
/// (|u_y v_z| + |u_z v_y|, ...). Shewchuk's bound (7 + 56 eps) eps, rounded up.
inline constexpr double orient3d_error_bound = 1e-15;

}  // namespace dlfl::detail

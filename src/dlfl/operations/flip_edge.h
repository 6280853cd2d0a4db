#pragma once
// flip_edge: an edge turned inside the union of its two faces, each end moving one step forward along its
// face. See docs/modeling.md.

#include <cstdint>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// Which way the ends of a flipped edge move along its two faces. A backward flip undoes a forward one on any
/// two faces (a forward flip is its own inverse only on two triangles).
enum class FlipDirection : std::uint8_t { forward, backward };

/// Throws ParameterError naming "edge" if `flip_edge` would refuse e: a removed edge; the same face on both
/// sides; a hole face beside it (a boundary edge); a face beside it with fewer than 3 sides; new ends at the
/// same vertex (a self-loop); an end vertex of e with fewer than 3 edges (it would be left hanging on one);
/// new ends already joined by an edge (it would double up); or a new end already on the other face (the face
/// it joins would pass through it twice). O(the valences of the four vertices).
void check_flip_edge(const Mesh& mesh, EdgeId e, FlipDirection direction = FlipDirection::forward);

/// Deletes e and draws the new edge between the corners that follow e's ends along its two faces: with
/// a = from(e), b = to(e), the face of side 0 running a, b, x, ... and that of side 1 running b, a, y, ...,
/// the new edge joins x and y (two triangles a-b-x and b-a-y: ab becomes xy). Both faces keep their sizes;
/// the new edge runs from x. On two triangles the flip is its own inverse up to direction (flipping the new
/// edge gives an edge between a and b again); in general it turns the edge one step around the union of the
/// two faces (p + q - 2 corners for a p-gon and a q-gon).
///
/// `FlipDirection::backward` moves each end one step back instead: the new edge joins the corners before a
/// along side 0's face and before b along side 1's, which turns the edge one step the other way, so that a
/// backward flip of a forward-flipped edge gives an edge between a and b again on faces of any sizes.
///
/// Counts: V+0, E+0, F+0 (the faces may be renumbered). Validates with `check_flip_edge` first. O(the smaller
/// face).
EdgeId flip_edge(Transaction& tx, EdgeId e, FlipDirection direction = FlipDirection::forward);

}  // namespace dlfl

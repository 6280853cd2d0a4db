#pragma once
// reverse_orientation: every face of the mesh turned the other way round (its corners in the opposite order),
// so that outward becomes inward; the one operation that changes the sign of a closed mesh's volume.

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// Reverses every face: a face v_0, v_1, ..., v_{n-1} becomes v_{n-1}, ..., v_1, v_0. Counts unchanged: V+0,
/// E+0, F+0. Through the Euler operators only: every edge is deleted, which leaves a point sphere at each
/// vertex, and inserted again in the reverse order into the mirrored angles (the rotation of edges around
/// each vertex reversed), then the faces get their hole flags back.
///
/// Handles: vertices keep theirs, with their positions and named attributes. Edges, faces and corners are
/// made anew; a few old face and corner handles stay alive for other elements (the point spheres' faces and
/// corners are reused by the operators). Named attributes follow the elements: an edge's value goes to the
/// new edge between the same two vertices that stands for it, a face's to its reversed face (as the hole
/// flag), a corner's to the corner of the same vertex in the same (reversed) face. Reversing twice gives back
/// the same faces, flags and values under other handles.
///
/// Cost: each deletion and each insertion relabels the smaller of the faces it joins or splits, which is
/// O(size log size) for the mesh in all; a handle (genus > 0) can cost up to the size of its face more.
void reverse_orientation(Transaction& tx);

}  // namespace dlfl

#pragma once
// crust: an inner, reversed copy of every component, a thickness below it, so that each closed surface
// becomes a hollow solid's two walls (docs/modeling.md, "Shells and frames").

#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct CrustOptions {
  /// How far each inner vertex lies below its outer one, along the vertex normal (`vertex_normal`). > 0.
  double thickness = 0.1;
};

/// Adds the inner copy: vertex v's copy at position(v) - thickness * vertex_normal(v) (a vertex with no
/// normal, such as a point sphere, is copied in place), every face reversed, hole flags copied. On a closed
/// mesh: V+V, E+E, F+F: twice the components and twice the Euler characteristic; the copy's signed volume
/// is negative, so the total is the shell's. Each hole face (of n sides) is then joined to its twin by a tube
/// of n quads (connect_faces), which closes an open sheet into one closed shell: in all V+V, E+E+h, F+F+h-2H
/// for H hole faces of h sides in all. Returns the copies of the vertices, in the order of their handles.
/// Refuses (ParameterError naming "thickness", nothing changed) a thickness not finite or not > 0, and one
/// that would put an inner vertex at a non-finite position. O(size), plus the size of a component per handle
/// of it.
std::vector<VertexId> crust(Transaction& tx, const CrustOptions& options = {});

/// The checks of crust, without changing anything.
void check_crust(const Mesh& mesh, const CrustOptions& options);

}  // namespace dlfl

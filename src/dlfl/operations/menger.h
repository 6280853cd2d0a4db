#pragma once
// menger: a Menger-sponge cut of every face, after TopMod's sponge: each face becomes a frame of cells
// around a centre face, and a tunnel leads from every centre face down to a skeleton of the mesh inside it,
// where the tunnels meet (docs/modeling.md, "High genus").

#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct MengerOptions {
  /// The centre face's size, as a share of its face's (scaled about the face's centroid), and the share of
  /// each edge between its two cuts. In (0, 1).
  double scale = 1.0 / 3.0;
  /// How deep the tunnels go, in mean edge lengths of their faces. > 0.
  double depth = 1.0 / 3.0;
};

/// Cuts every edge in three (at (1 - scale) / 2 of its length from each end) and every face of n sides into
/// a grid of 2n + 1 cells: a quad at each corner, a quad along each edge's middle piece, and the centre
/// n-gon, whose corners lie at centroid + scale (corner - centroid). Adds the skeleton: a mirrored copy of
/// the mesh as it was (detail/shell_copy.h), vertex v's copy at the average, over the surface faces around
/// v, of v's corner of the centre face moved by depth x (the face's mean edge length) against the face's
/// unit normal. Then joins every centre face to its twin in the skeleton by a tunnel of n quads
/// (connect_faces), so no face of the skeleton is left: the tunnels meet along its edges. On the cube with
/// the defaults this is the level-1 Menger sponge, exactly; applied again, every cell gets its tunnel.
///
/// Counts, for V vertices and E edges without the point spheres (left as they are): V' = 2V + 4E,
/// E' = 12E, F' = 6E, every face a quad: 4E cells (at the corners and along the edges) and 2E tunnel walls.
/// V' - E' + F' = 2V - 2E: a connected input gives one closed component of genus E - V + 1 (cube 5,
/// tetrahedron 3). Hole faces are cut and tunnelled like the others, and what is made from a hole face
/// (its cells and its tunnel) stays a hole. Returns the skeleton's vertices, in the order of the vertices
/// they copy.
///
/// Refuses (ParameterError, nothing changed): `scale` not finite or outside (0, 1); `depth` not finite or
/// not > 0; a vertex of valence 1 (naming "scale"); positions that would not be finite (the cells' naming
/// "scale", the skeleton's "depth"). O(size of the mesh), plus the size of a component per handle of it (the
/// mirrored copy's cost).
std::vector<VertexId> menger(Transaction& tx, const MengerOptions& options = {});

/// The checks of menger, without changing anything.
void check_menger(const Mesh& mesh, const MengerOptions& options);

}  // namespace dlfl

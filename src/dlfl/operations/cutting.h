#pragma once
// The cutting operations (docs/modeling.md, "Cutting"): truncate_vertex, chamfer_edge and cut_face. Each cuts
// "caps" off the mesh (a vertex, an edge with its two ends, a face with its corners): every other edge that
// leaves a cap is cut at `offset` of its length from it, the cut points are joined across the faces around,
// and the cap is removed, leaving one new face. The Euler characteristic, the orientation and the hole faces
// elsewhere are kept.

#include <span>
#include <string_view>
#include <vector>

#include <dlfl/handles.h>
#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// The faces a cut made, one per cut element in the order given, and the vertices it put on the edges that
/// leave the cut elements (the corners of those faces), in the order they were made.
struct CutResult {
  std::vector<FaceId> faces;
  std::vector<VertexId> vertices;
};

/// The options of truncate_vertex, chamfer_edge and cut_face.
struct CutOptions {
  /// Where each edge leaving a cut element is cut, as a share of its length from that element, in (0, 0.5):
  /// below 0.5 the cuts of two neighbouring cut elements never meet.
  double offset = 0.25;
};

/// The options of each of the three, by its own name.
using TruncateVertexOptions = CutOptions;
using ChamferEdgeOptions = CutOptions;
using CutFaceOptions = CutOptions;

// ---- truncate_vertex: a vertex of valence k becomes a k-gon: V+k-1, E+k, F+1.

/// Cuts `vertex` off: each of its k edges gets a new vertex at `offset` of its length from it, the new
/// vertices are joined across each face around it, and the vertex with its stubs is removed, leaving a
/// k-gon (a hole face if a hole face was around the vertex: the cut then widens the boundary). V+k-1, E+k,
/// F+1. Refusals (ParameterError naming "vertex" or "offset", before any change): a removed vertex, a vertex
/// with fewer than 2 edges, an offset outside (0, 0.5) or not finite, cut points that would not be finite.
/// O(the faces around the vertex).
CutResult truncate_vertex(Transaction& tx, VertexId vertex, const TruncateVertexOptions& options = {});

/// Truncates every vertex of the list as one operation; the counts add up (a vertex listed twice is
/// refused; an edge joining two listed vertices gets two new vertices). Refusals name "vertices".
CutResult truncate_vertices(Transaction& tx, std::span<const VertexId> vertices,
                            const TruncateVertexOptions& options = {});

/// The checks of truncate_vertices, refusals naming `parameter`.
void check_truncate_vertices(const Mesh& mesh, std::span<const VertexId> vertices,
                             const TruncateVertexOptions& options, std::string_view parameter = "vertices");

// ---- chamfer_edge: an edge becomes a new face. For an edge whose ends have valences a and b: V+a+b-4,
// E+a+b-3, F+1 (on a cube, V+2, E+3, F+1).

/// Cuts `edge` off with its two end vertices: each of the a + b - 2 other edges at its ends gets a new
/// vertex at `offset` of its length from the end, the new vertices are joined across each face around the
/// edge, and the edge, its ends and the stubs are removed, leaving an (a + b - 2)-gon (a hole face if a hole
/// face was around: the cut widens the boundary). Refusals (ParameterError naming "edge" or "offset", before
/// any change): a removed edge, fewer than 2 other edges at its ends, another edge joining its ends, an
/// offset outside (0, 0.5), cut points that would not be finite. O(the faces around the edge's ends).
CutResult chamfer_edge(Transaction& tx, EdgeId edge, const ChamferEdgeOptions& options = {});

/// Chamfers every edge of the list as one operation; the counts add up. Two listed edges that share an end
/// are refused (their cuts would meet); an edge joining the ends of two listed edges gets two new vertices.
/// Refusals name "edges".
CutResult chamfer_edges(Transaction& tx, std::span<const EdgeId> edges,
                        const ChamferEdgeOptions& options = {});

/// The checks of chamfer_edges, refusals naming `parameter`.
void check_chamfer_edges(const Mesh& mesh, std::span<const EdgeId> edges, const ChamferEdgeOptions& options,
                         std::string_view parameter = "edges");

// ---- cut_face: TopMod's "cut by face": the face is sliced off with its corners, the cut running across the
// edges that leave the face. For a face of n sides whose vertices send out m = sum (valence - 2) edges
// besides the face's own: V+m-n, E+m-n, F+0 (nothing on a prism, where m = n).

/// Cuts `face` off: each edge that leaves a corner of the face (not one of its sides) gets a new vertex at
/// `offset` of its length from the face, the new vertices are joined across each face around, and the face
/// with its vertices, sides and the stubs is removed, leaving an m-gon in its place (a hole face if a hole
/// face was around: the cut widens the boundary). Refusals (ParameterError naming "face" or "offset", before
/// any change): a removed, hole or point-sphere face, a face that visits a vertex twice, fewer than 2 edges
/// leaving it, an edge leaving it that comes back to it, an offset outside (0, 0.5), cut points that would
/// not be finite. O(the faces around the face's corners).
CutResult cut_face(Transaction& tx, FaceId face, const CutFaceOptions& options = {});

/// Cuts every face of the list as one operation; the counts add up. Two listed faces that share a vertex are
/// refused (their cuts would meet); an edge joining two listed faces gets two new vertices. Refusals name
/// "faces".
CutResult cut_faces(Transaction& tx, std::span<const FaceId> faces, const CutFaceOptions& options = {});

/// The checks of cut_faces, refusals naming `parameter`.
void check_cut_faces(const Mesh& mesh, std::span<const FaceId> faces, const CutFaceOptions& options,
                     std::string_view parameter = "faces");

}  // namespace dlfl

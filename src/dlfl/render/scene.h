#pragma once
// What a picture shows, in one flat form for meshes and cell complexes alike: coloured polygons, edges
// (drawn on request), curves and points (always drawn), over one array of positions.

#include <cstdint>
#include <vector>

#include <dlfl/cells/cell_complex.h>
#include <dlfl/indexed_lists.h>
#include <dlfl/mesh.h>
#include <dlfl/render/colors.h>
#include <dlfl/render/image.h>

namespace dlfl {

/// The polygons are the lists (IndexedLists): polygon i uses `indices[offsets[i] .. offsets[i+1])`
/// (positions, in order) and is filled with `polygon_colors[i]`. `edges`, `curves` hold pairs of position
/// indices, `points` single ones.
struct RenderScene : IndexedLists {
  std::vector<Rgba> polygon_colors;
  std::vector<std::uint32_t> edges;   ///< the polygons' edges, drawn when edges are on
  std::vector<std::uint32_t> curves;  ///< 1-cells: always drawn, thicker
  std::vector<std::uint32_t> points;  ///< 0-cells and point spheres: always drawn
  /// The polygons have a consistent outside (a mesh): faces seen from behind are tinted, and smooth shading
  /// may average their normals. Cell complexes have no such orientation.
  bool oriented = true;
  /// No face is ever seen from behind (a closed mesh): a vector drawing may leave back faces out.
  bool closed = true;

  std::size_t num_polygons() const { return num_lists(); }
};

/// Newell's vector of polygon f: its normal (outward for a face counter-clockwise seen from outside), twice
/// its area long. O(size of f).
glm::dvec3 polygon_newell(const RenderScene& scene, std::size_t f);

/// A mesh as a scene: every surface face of 3 or more corners a polygon coloured by `color_by`
/// (`face_colors`), every edge with a surface face on a side an edge, point spheres as points. Hole faces
/// are left out, so an open mesh looks open. Throws what `face_colors` throws. O(size of the mesh).
RenderScene mesh_scene(const Mesh& mesh, const ColorBy& color_by = {});

/// A cell complex as a scene: quads (2-cells) and the boundary quads of hexahedra (the faces of exactly one
/// hexahedron) as polygons, their sides as edges, 1-cells as curves, 0-cells as points. Quads are coloured
/// `face_size_color(4)`, or `plain_color` under Mode::none; other modes throw ParameterError naming
/// "color_by". Not oriented. O(cells log cells).
RenderScene cell_scene(const CellComplex& complex, const ColorBy& color_by = {});

}  // namespace dlfl

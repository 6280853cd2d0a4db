#pragma once
// Polygon soup -> DLFL, in O(size).

#include <cstddef>
#include <cstdint>

#include <dlfl/errors.h>
#include <dlfl/mesh.h>
#include <dlfl/polygon_soup.h>

namespace dlfl {

/// A polygon soup that is not an orientable 2-manifold (with or without boundary). `element()` says whether
/// the problem is at a face or a vertex of the input and `index()` which one, so readers can point at a file
/// line.
class PolygonError : public TopologyError {
 public:
  enum class Element { vertex, face };
  PolygonError(Element element, std::size_t index, const std::string& message)
      : TopologyError(message), element_(element), index_(index) {}
  Element element() const { return element_; }
  std::size_t index() const { return index_; }

 private:
  Element element_;
  std::size_t index_;
};

/// How the messages of build_mesh number the soup's vertices and faces: as the file it came from does. By
/// default they are the soup's indices (which are the handles); with another first number, the handle
/// follows in parentheses ("face 3 (f2)").
struct SoupNumbering {
  std::uint32_t first_vertex = 0;  ///< the number of vertex 0: 1 for OBJ, whose indices start at 1
  std::uint32_t first_face = 0;    ///< the number of face 0: 1 for files, "face 3" being the third face
};

/// Builds the DLFL of a polygon soup in O(size), pairing half-edges through a hash map of directed edges.
///
/// Handles are predictable: vertex i of the soup is VertexId(i), face i is FaceId(i), and the corner of the
/// j-th vertex of face i is CornerId(offsets[i] + j). Each boundary loop then becomes a hole face (appended
/// after the soup's faces), and each vertex that no face uses becomes a point sphere. An edge's side 0 is its
/// corner with the smaller handle.
///
/// Throws PolygonError for: a non-finite position, a face with fewer than 3 vertices, an index out of range,
/// a vertex used twice in a row, a directed edge used twice (an edge shared by more than two faces, or two
/// faces with opposite orientation), and a non-manifold vertex (its faces form more than one fan); and
/// InvalidArgument for offsets that do not describe the index list (not starting at 0, not ending at its
/// size, or decreasing).
Mesh build_mesh(const PolygonSoup& soup, const SoupNumbering& numbering = {});

/// The polygons of a mesh for writing: the open surface's vertices (see `statistics`: every live vertex but
/// the inner vertices of a hole covered by several hole faces) in handle order, renumbered densely, and every
/// live face that is neither a hole nor a point sphere. Throws TopologyError if a face has 2 corners or two
/// edges join the same two vertices: an indexed polygon list cannot represent those (save in the native JSON
/// format instead).
PolygonSoup to_polygons(const Mesh& mesh);

}  // namespace dlfl

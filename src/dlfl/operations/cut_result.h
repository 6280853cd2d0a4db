#pragma once
// What the cutting operations (truncate_vertex, chamfer_edge, cut_face; docs/modeling.md, "Cutting") make.

#include <vector>

#include <dlfl/handles.h>

namespace dlfl {

/// The faces a cut made, one per cut element in the order given, and the vertices it put on the edges that
/// leave the cut elements (the corners of those faces), in the order they were made.
struct CutResult {
  std::vector<FaceId> faces;
  std::vector<VertexId> vertices;
};

}  // namespace dlfl

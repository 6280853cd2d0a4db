#pragma once
// CREATEFACEMANIFOLD: a two-sided polygon, built exactly as the honeycomb paper (section 4) builds it.

#include <glm/vec3.hpp>
#include <span>

#include <dlfl/mesh.h>

namespace dlfl {

/// The two faces of a face manifold. The front face runs v_0, v_1, ..., v_{N-1} from its first corner; the
/// back face runs v_{N-1}, ..., v_1, v_0 from its first corner.
struct FaceManifold {
  FaceId front;
  FaceId back;
};

/// Adds a new component: N `create_vertex` calls, then `insert_edge(v_i, v_{i+1})` for i = 0..N-1. The result
/// is two N-gons sharing N edges (genus 0). Edge i runs from v_i to v_{i+1 mod N} on its side 0.
///
/// Optional outputs, each empty or of size N: `vertices[i]` = v_i, `front_corners[i]` and `back_corners[i]` =
/// the corner of v_i in the front and back face. Throws InvalidArgument (mesh unchanged) for fewer than 2
/// points, a non-finite point, or an output span of the wrong size.
FaceManifold create_face_manifold(Mesh& mesh, std::span<const glm::dvec3> positions,
                                  std::span<VertexId> vertices = {}, std::span<CornerId> front_corners = {},
                                  std::span<CornerId> back_corners = {});

}  // namespace dlfl

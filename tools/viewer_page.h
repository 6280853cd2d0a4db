#pragma once
// The page `dlfl view` writes: the viewer's template (tools/viewer/, embedded at build time) with the meshes'
// data inline, one self-contained HTML file. Layout of the data and the viewer's controls: docs/viewer.md.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include <dlfl/mesh.h>

namespace dlfl::tool {

/// One mesh of the slider (M_k), reduced to what the viewer draws: the surface faces cut into triangles
/// (fans from each face's first corner; hole faces left out), each triangle coloured by the size of its face
/// (dlfl/render/colors.h, as the renderer), and the edges that have a surface face on a side.
struct ViewerStep {
  std::string label;                          // "M_2", "subdivide honeycomb", ...
  std::string counts;                         // "V 26, E 48, F 24, 2 holes"
  std::vector<float> positions;               // x, y, z per vertex, relative to the page's centre
  std::vector<std::uint32_t> triangles;       // three vertex indices per triangle, counter-clockwise
  std::vector<std::uint8_t> triangle_colors;  // r, g, b per triangle
  std::vector<std::uint32_t> edges;           // two vertex indices per edge
  std::vector<std::pair<std::uint32_t, std::size_t>> face_sizes;  // sides -> surface faces, for the legend
  glm::dvec3 bbox_min{0.0}, bbox_max{0.0};  // of the surface, relative to the page's centre
  std::size_t faces = 0;                    // surface faces
};

/// The steps of a page. The first mesh added fixes the centre that every step's positions are taken from,
/// so that float coordinates keep their precision near the mesh.
class ViewerPage {
 public:
  /// `max_faces` bounds the surface faces of all steps together (a browser holds a few hundred bytes per
  /// face); `add` refuses a step past it.
  explicit ViewerPage(std::size_t max_faces) : max_faces_(max_faces) {}

  /// Throws Error if the surface faces of the pages' steps would pass `max_faces`, naming `faces_to_come`
  /// (the faces of the steps planned) in the message.
  void check_room(std::size_t faces_to_come) const;
  /// Appends `mesh` as the next step (check_room first).
  void add(const Mesh& mesh, std::string label);

  std::size_t steps() const { return steps_.size(); }
  std::size_t faces() const { return faces_; }

  /// The whole page: the viewer's template with the steps' data; `title` names the page.
  void write(std::ostream& out, const std::string& title) const;

 private:
  std::size_t max_faces_;
  std::size_t faces_ = 0;
  std::optional<glm::dvec3> centre_;
  std::vector<ViewerStep> steps_;
};

}  // namespace dlfl::tool

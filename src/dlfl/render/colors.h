#pragma once
// The colours of a picture: what each face is filled with (`--color-by`), and the fixed colours of the
// background, edges, curves, points and back faces.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/render/image.h>

namespace dlfl {

/// How faces are coloured.
struct ColorBy {
  enum class Mode {
    none,       ///< every face `plain_color`
    face_size,  ///< `face_size_color(size)`: one fixed colour per face size (hexagons one colour)
    component,  ///< `palette_color(k)` for the k-th connected component (in order of the faces' handles)
    hole,       ///< faces across an edge from the k-th hole face `palette_color(k)`, the others `plain_color`
    attribute,  ///< a numeric or boolean face or vertex attribute through `ramp_color` (see `face_colors`)
    concave,    ///< the faces beside a concave edge (`concave_edges`, the lateral artifacts) `concave_color`
  };
  Mode mode = Mode::face_size;
  std::string attribute;  ///< the attribute's name, for Mode::attribute
};

/// "none", "face-size", "component", "hole", "concave" or "attribute=NAME". Throws ParameterError naming
/// "color_by" otherwise (an empty NAME included).
ColorBy parse_color_by(std::string_view text);

/// The colour of faces of `size` corners: 3 blue, 4 green, 5 orange, 6 pale sand, 7 red, 8 violet, 9 teal,
/// 10 pink, 11 and more dark grey, 1 and 2 light grey. Hexagons, the bulk of a honeycomb mesh, get the
/// quietest colour, so that its other faces stand out.
Rgba face_size_color(std::size_t size);

/// Distinct colours for indices 0, 1, 2, ...: hues a golden angle apart, pastel.
Rgba palette_color(std::size_t index);

/// A colour ramp from t = 0 (dark blue) over teal and yellow to t = 1 (red-orange); t is clamped to [0, 1],
/// NaN gives mid grey.
Rgba ramp_color(double t);

inline constexpr Rgba plain_color{201, 211, 224, 255};  ///< faces under Mode::none
inline constexpr Rgba edge_color{38, 38, 46, 255};
inline constexpr Rgba curve_color{24, 52, 120, 255};    ///< 1-cells of a cell complex
inline constexpr Rgba point_color{150, 30, 30, 255};    ///< 0-cells and point spheres
inline constexpr Rgba back_color{200, 80, 70, 255};     ///< mixed into the faces seen from behind
inline constexpr Rgba concave_color{214, 40, 40, 255};  ///< faces beside a concave edge (Mode::concave)

/// The fill colour of every face of `mesh`, indexed by face handle (`face_capacity()` entries; hole faces
/// and removed faces get `plain_color`, and are not drawn anyway). For Mode::attribute the attribute is
/// looked up among face attributes first, then vertex attributes; a face takes the mean of its corners'
/// vertex values. Booleans count as 0 and 1; numbers are mapped linearly from their smallest to their
/// largest finite value over the surface faces to t in [0, 1] (all equal: t = 0.5). Throws ParameterError
/// naming "color_by" for an attribute that does not exist or holds points. Mode::concave: `concave_color` on
/// both faces of every edge that `concave_edges` (default tolerance) finds concave, `plain_color` elsewhere.
/// O(size of the mesh).
std::vector<Rgba> face_colors(const Mesh& mesh, const ColorBy& color_by);

}  // namespace dlfl

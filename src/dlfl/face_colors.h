#pragma once
// The face-size colour map that pictures of meshes share (the HTML viewer now, the renderer later): one fixed
// colour per number of sides, so that a honeycomb's hexagons are all one calm grey and every non-hexagon
// stands out, and a quad mesh is one green. Colours from the Okabe-Ito palette, which readers with the
// common colour-vision deficiencies can tell apart.

#include <cstdint>

namespace dlfl {

/// An sRGB colour, 8 bits per channel.
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  constexpr bool operator==(const Rgb8&) const = default;
};

/// The colour of a face of `sides` corners: triangles sky blue, quads bluish green, pentagons vermillion,
/// hexagons light grey, heptagons reddish purple, octagons yellow, larger faces blue; faces of fewer than 3
/// sides (point spheres, 2-gons) dark grey.
constexpr Rgb8 face_size_color(std::uint32_t sides) {
  constexpr Rgb8 by_size[] = {{0x40, 0x40, 0x40}, {0x56, 0xb4, 0xe9}, {0x00, 0x9e, 0x73}, {0xd5, 0x5e, 0x00},
                              {0xc8, 0xc8, 0xc8}, {0xcc, 0x79, 0xa7}, {0xf0, 0xe4, 0x42}, {0x00, 0x72, 0xb2}};
  // by_size[0] for fewer than 3 sides, then 3 to 8 sides, then the rest.
  return by_size[sides < 3 ? 0 : sides > 8 ? 7 : sides - 2];
}

}  // namespace dlfl

#pragma once
// A tiny built-in bitmap font (5 x 7 pixels per glyph) for the labels of contact sheets: digits, letters
// (lower case drawn as upper case) and . , : = - _ ( ) / + # and space; any other character is drawn as ?.

#include <string_view>

#include <dlfl/render/image.h>

namespace dlfl {

inline constexpr int glyph_width = 5;
inline constexpr int glyph_height = 7;
inline constexpr int glyph_advance = 6;  ///< glyph width plus one column of space

/// The width in pixels of `text` drawn at `scale` (each glyph pixel a scale x scale square).
inline int text_width(std::string_view text, int scale) {
  return text.empty() ? 0 : (static_cast<int>(text.size()) * glyph_advance - 1) * scale;
}

/// Draws `text` with its top-left corner at (x, y), clipped to the image.
void draw_text(Image& image, int x, int y, std::string_view text, Rgba color, int scale = 1);

}  // namespace dlfl

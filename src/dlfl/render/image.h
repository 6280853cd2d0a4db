#pragma once
// A picture in memory: RGBA, 8 bits per channel, rows top to bottom in one contiguous array.

#include <cstdint>
#include <string_view>
#include <vector>

namespace dlfl {

/// One pixel: red, green, blue and alpha (0 transparent, 255 opaque), straight (not premultiplied) alpha.
struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

/// Reads a colour: `#RRGGBB` or `#RRGGBBAA` (the `#` optional, hex digits in either case), or one of the
/// names `white`, `black`, `gray`, `grey`, `transparent`. Throws ParameterError naming `parameter` otherwise.
Rgba parse_color(std::string_view text, const char* parameter = "color");

/// `#rrggbb` (the alpha left out).
std::string_view hex_text(Rgba color, char (&buffer)[8]);

/// An RGBA8 image of `width` x `height` pixels; pixel (x, y) is `pixels[y * width + x]`, y = 0 the top row.
class Image {
 public:
  Image() = default;
  /// Throws InvalidArgument for a negative size or more than 2^28 pixels.
  Image(int width, int height, Rgba fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  Rgba& at(int x, int y) { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  const Rgba& at(int x, int y) const { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  const std::vector<Rgba>& pixels() const { return pixels_; }
  /// True if every pixel is opaque (then a PNG needs no alpha channel).
  bool opaque() const;

  /// Copies `source` with its top-left corner at (x, y), clipped to this image.
  void paste(const Image& source, int x, int y);
  /// Fills the rectangle [x, x + w) x [y, y + h), clipped to this image.
  void fill(int x, int y, int w, int h, Rgba color);

  friend bool operator==(const Image&, const Image&) = default;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Rgba> pixels_;
};

}  // namespace dlfl

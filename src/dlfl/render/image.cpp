#include <dlfl/render/image.h>

#include <algorithm>
#include <string>

#include <dlfl/errors.h>

namespace dlfl {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

Rgba parse_color(std::string_view text, const char* parameter) {
  if (text == "white") return {255, 255, 255, 255};
  if (text == "black") return {0, 0, 0, 255};
  if (text == "gray" || text == "grey") return {128, 128, 128, 255};
  if (text == "transparent") return {255, 255, 255, 0};
  std::string_view digits = text.starts_with('#') ? text.substr(1) : text;
  std::uint8_t channels[4] = {0, 0, 0, 255};
  bool good = digits.size() == 6 || digits.size() == 8;
  for (std::size_t i = 0; good && i < digits.size(); i += 2) {
    const int high = hex_digit(digits[i]), low = hex_digit(digits[i + 1]);
    good = high >= 0 && low >= 0;
    channels[i / 2] = static_cast<std::uint8_t>(16 * high + low);
  }
  if (!good) {
    throw ParameterError(std::string(parameter) +
                             ": expected #RRGGBB, #RRGGBBAA or a colour name (white, black, "
                             "gray, transparent), got '" +
                             std::string(text) + "'",
                         parameter);
  }
  return {channels[0], channels[1], channels[2], channels[3]};
}

std::string_view hex_text(Rgba color, char (&buffer)[8]) {
  static constexpr char digits[] = "0123456789abcdef";
  const std::uint8_t channels[3] = {color.r, color.g, color.b};
  buffer[0] = '#';
  for (int i = 0; i < 3; ++i) {
    buffer[1 + 2 * i] = digits[channels[i] >> 4];
    buffer[2 + 2 * i] = digits[channels[i] & 15];
  }
  buffer[7] = '\0';
  return {buffer, 7};
}

Image::Image(int width, int height, Rgba fill) : width_(width), height_(height) {
  if (width < 0 || height < 0 || static_cast<double>(width) * height > double(1 << 28)) {
    throw InvalidArgument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                          " is negative or above 2^28 pixels");
  }
  pixels_.assign(static_cast<std::size_t>(width) * height, fill);
}

bool Image::opaque() const {
  return std::all_of(pixels_.begin(), pixels_.end(), [](Rgba p) { return p.a == 255; });
}

void Image::paste(const Image& source, int x, int y) {
  const int x0 = std::max(0, x), x1 = std::min(width_, x + source.width());
  for (int row = std::max(0, y); row < std::min(height_, y + source.height()); ++row) {
    for (int col = x0; col < x1; ++col) at(col, row) = source.at(col - x, row - y);
  }
}

void Image::fill(int x, int y, int w, int h, Rgba color) {
  const int x0 = std::max(0, x), x1 = std::min(width_, x + w);
  if (x1 <= x0) return;  // wholly left or right of the image
  for (int row = std::max(0, y); row < std::min(height_, y + h); ++row) {
    std::fill(pixels_.begin() + static_cast<std::ptrdiff_t>(row) * width_ + x0,
              pixels_.begin() + static_cast<std::ptrdiff_t>(row) * width_ + x1, color);
  }
}

}  // namespace dlfl

#include <dlfl/render/contact_sheet.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/render/font.h>

namespace dlfl {

namespace {

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return lines;
    start = end + 1;
  }
}

}  // namespace

Image contact_sheet(std::span<const Image> pictures, std::span<const std::string> captions, Rgba background,
                    Rgba text_color) {
  if (pictures.empty()) throw InvalidArgument("contact sheet: no pictures");
  if (captions.size() != pictures.size()) throw InvalidArgument("contact sheet: one caption per picture");
  const int w = pictures[0].width(), h = pictures[0].height();
  for (const Image& p : pictures) {
    if (p.width() != w || p.height() != h)
      throw InvalidArgument("contact sheet: pictures of different sizes");
  }
  const int count = static_cast<int>(pictures.size());
  const int columns = count <= 5 ? count : static_cast<int>(std::ceil(std::sqrt(double(count))));
  const int rows = (count + columns - 1) / columns;
  const int scale = w >= 240 ? 2 : 1;
  const int line_height = (glyph_height + 3) * scale;
  std::size_t most_lines = 1;
  for (const std::string& c : captions) most_lines = std::max(most_lines, lines_of(c).size());
  const int strip = static_cast<int>(most_lines) * line_height + 4 * scale;
  Image sheet(columns * w, rows * (h + strip), background);
  for (int k = 0; k < count; ++k) {
    const int x = (k % columns) * w, y = (k / columns) * (h + strip);
    sheet.paste(pictures[k], x, y);
    // Drawn on a strip of the picture's width, so that a long caption is cut at its own picture's sides.
    Image caption(w, strip, background);
    int line_y = 2 * scale;
    for (std::string_view line : lines_of(captions[k])) {
      draw_text(caption, (w - text_width(line, scale)) / 2, line_y, line, text_color, scale);
      line_y += line_height;
    }
    sheet.paste(caption, x, y + h);
  }
  return sheet;
}

}  // namespace dlfl

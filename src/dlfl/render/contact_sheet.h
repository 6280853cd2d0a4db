#pragma once
// Pictures side by side, each with a caption under it: M_0 ... M_N of a scheme, or the steps of a log.

#include <span>
#include <string>

#include <dlfl/render/image.h>

namespace dlfl {

/// The pictures in a grid (one row for up to 5, else about as many columns as rows), in order, each above
/// its caption (lines split at '\n', centred, in the built-in font, cut at the sides of its picture). All
/// pictures must have the size of the first; the captions' strip is as high as the tallest caption needs.
/// Throws InvalidArgument for no pictures, a different number of captions, or pictures of different sizes.
Image contact_sheet(std::span<const Image> pictures, std::span<const std::string> captions, Rgba background,
                    Rgba text_color = {30, 30, 30, 255});

}  // namespace dlfl

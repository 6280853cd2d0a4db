#pragma once
// PNG files through libpng (Debian's libpng-dev), the reference implementation of the format.

#include <filesystem>
#include <iosfwd>

#include <dlfl/render/image.h>

namespace dlfl {

class FileBatch;

/// Writes `image` as an 8-bit PNG to `out`: RGB when every pixel is opaque, RGBA otherwise. Throws IoError
/// if libpng reports an error or the stream fails.
void write_png(const Image& image, std::ostream& out);

/// Writes `image` to the file `path` atomically (dlfl/io/atomic_file.h): nothing is left there unless all
/// of it is written. With a `batch`, only stages it there, to be replaced when the batch commits. Throws
/// IoError naming `path`; throws InvalidArgument for an empty image, before any file is touched.
void write_png(const Image& image, const std::filesystem::path& path, FileBatch* batch = nullptr);

}  // namespace dlfl

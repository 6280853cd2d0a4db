#pragma once
// Internal: the OBJ statement loop, shared by the serial parser (obj.cpp) and the chunked parallel one
// (obj_chunks.cpp) so that both read every line alike. Not part of the API.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/parsed_polygons.h>

namespace dlfl::io_detail {

/// Reads the OBJ statements of the scanner's text: calls `vertex(point, line)` for each `v`, and for each `f`
/// appends its 0-based indices to `indices` and calls `face(line)`. `defined` is the number of vertices the
/// file defines before the text (for negative indices). Other statements are skipped. Throws IoError at the
/// line of a malformed statement.
template <class Vertex, class Face>
void scan_obj_lines(LineScanner& s, std::int64_t defined, std::vector<std::uint32_t>& indices,
                    Vertex&& vertex, Face&& face) {
  while (s.next_line()) {
    const std::string_view keyword = s.token();
    if (keyword == "v") {
      // A 4th value (w) or vertex colours may follow x y z; they are ignored.
      vertex(s.point(), s.line());
      ++defined;
    } else if (keyword == "f") {
      // Negative indices count back from the vertices read so far; positive ones are checked after the whole
      // file, so that a face may name a vertex defined further down.
      std::size_t count = 0;
      while (!s.at_eol()) {
        indices.push_back(obj_vertex_index(s, defined));
        ++count;
      }
      if (count < 3) s.fail(face_size_error(std::int64_t(count)));
      if (indices.size() > max_indices) s.fail("too many face vertices");
      face(s.line());
    }
  }
}

/// The serial OBJ parser: the reference that the chunked one matches, and the one that reports errors.
ParsedPolygons parse_obj_serial(std::string_view text, const std::string& name);

/// Bytes per chunk of the chunked OBJ parser: a fixed size, so that the chunks never depend on the thread
/// count; large enough that a chunk's bookkeeping costs nothing beside its parsing.
inline constexpr std::size_t obj_chunk_bytes = std::size_t{1} << 20;

/// The OBJ parser on several threads: the text is cut into chunks of about `chunk_bytes` at line starts, a
/// first pass counts each chunk's lines, `v` and `f` statements, and a second parses the chunks at once into
/// their places. The result is the serial parser's; on any error the serial parser runs to report it, so
/// the messages are its own too.
ParsedPolygons parse_obj_chunked(std::string_view text, const std::string& name,
                                 std::size_t chunk_bytes = obj_chunk_bytes);

}  // namespace dlfl::io_detail

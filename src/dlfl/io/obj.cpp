// Wavefront OBJ: `v` and `f` statements; everything else is skipped.

#include <vector>

#include <dlfl/io/detail/obj_lines.h>
#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/detail/write_in_parts.h>
#include <dlfl/io/obj.h>
#include <dlfl/thread_count.h>

namespace dlfl {

namespace io_detail {

ParsedPolygons parse_obj_serial(std::string_view text, const std::string& name) {
  ParsedPolygons parsed;
  parsed.numbering.first_vertex = 1;  // OBJ indices start at 1
  PolygonSoup& soup = parsed.soup;
  LineScanner s(text, name, true);
  scan_obj_lines(
      s, 0, soup.indices,
      [&](const glm::dvec3& p, std::size_t line) {
        soup.positions.push_back(p);
        parsed.vertex_lines.push_back(line);
      },
      [&](std::size_t line) { end_face(parsed, line); });
  check_obj_indices(
      soup.num_faces(), [&](std::size_t f) { return soup.face(f); }, parsed.face_lines, soup.positions.size(),
      name);
  return parsed;
}

// The chunked parser's extra pass pays only with threads to share the chunks, and a file of more than one.
ParsedPolygons parse_obj_text(std::string_view text, const std::string& name) {
  const bool chunked = text.size() > obj_chunk_bytes && thread_count() > 1;
  return chunked ? parse_obj_chunked(text, name) : parse_obj_serial(text, name);
}

}  // namespace io_detail

void write_obj(std::ostream& out, const PolygonSoup& soup) {
  io_detail::BlockWriter w(out);
  std::vector<io_detail::TextWriter> pool;
  io_detail::write_in_parts(w, soup.positions.size(), pool, [&](auto& part, std::size_t b, std::size_t e) {
    for (std::size_t v = b; v < e; ++v) {
      part.text("v ");
      part.point_line(soup.positions[v]);
    }
  });
  io_detail::write_in_parts(w, soup.num_faces(), pool, [&](auto& part, std::size_t b, std::size_t e) {
    for (std::size_t f = b; f < e; ++f) {
      part.put('f');
      for (std::uint32_t i : soup.face(f)) {
        part.put(' ');
        part.number(std::uint64_t{i} + 1);
      }
      part.put('\n');
    }
  });
  w.flush();
}

}  // namespace dlfl

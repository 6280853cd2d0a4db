// Wavefront OBJ: `v` and `f` statements; everything else is skipped.

#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/obj.h>

namespace dlfl {

namespace io_detail {

ParsedPolygons parse_obj_text(std::string_view text, const std::string& name) {
  ParsedPolygons parsed;
  parsed.numbering.first_vertex = 1;  // OBJ indices start at 1
  PolygonSoup& soup = parsed.soup;
  LineScanner s(text, name, true);
  while (s.next_line()) {
    const std::string_view keyword = s.token();
    if (keyword == "v") {
      // A 4th value (w) or vertex colours may follow x y z; they are ignored.
      soup.positions.push_back(s.point());
      parsed.vertex_lines.push_back(s.line());
    } else if (keyword == "f") {
      // Negative indices count back from the vertices read so far; positive ones are checked after the whole
      // file, so that a face may name a vertex defined further down.
      const auto defined = static_cast<std::int64_t>(soup.positions.size());
      std::size_t count = 0;
      while (!s.at_eol()) {
        soup.indices.push_back(obj_vertex_index(s, defined));
        ++count;
      }
      if (count < 3) s.fail(face_size_error(std::int64_t(count)));
      if (soup.indices.size() > max_indices) s.fail("too many face vertices");
      end_face(parsed, s.line());
    }
  }
  check_obj_indices(
      soup.num_faces(), [&](std::size_t f) { return soup.face(f); }, parsed.face_lines, soup.positions.size(),
      name);
  return parsed;
}

}  // namespace io_detail

void write_obj(std::ostream& out, const PolygonSoup& soup) {
  io_detail::BlockWriter w(out);
  for (const glm::dvec3& p : soup.positions) {
    w.text("v ");
    w.point_line(p);
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    w.put('f');
    for (std::uint32_t i : soup.face(f)) {
      w.put(' ');
      w.number(std::uint64_t{i} + 1);
    }
    w.put('\n');
  }
  w.flush();
}

}  // namespace dlfl

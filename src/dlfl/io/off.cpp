// Geomview OFF, ASCII: a header keyword, the counts, one vertex per line, one face per line.

#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/off.h>

namespace dlfl {

namespace io_detail {
namespace {

// The prefixes ST (texture coordinates), C (colour) and N (normal) only add values after x y z on each vertex
// line, which the line-based reader ignores; 4 (4-D) and n (n-D) change the vertex layout and are refused.
void check_header(LineScanner& s, std::string_view keyword) {
  std::string_view k = keyword;
  if (k.starts_with("ST")) k.remove_prefix(2);
  if (k.starts_with("C")) k.remove_prefix(1);
  if (k.starts_with("N")) k.remove_prefix(1);
  if (k == "OFF") return;
  if (keyword.ends_with("OFF")) s.fail("unsupported OFF variant '" + std::string(keyword) + "'");
  s.fail("missing OFF header (found '" + std::string(keyword) + "')");
}

}  // namespace

ParsedPolygons parse_off_text(std::string_view text, const std::string& name) {
  ParsedPolygons parsed;
  PolygonSoup& soup = parsed.soup;
  LineScanner s(text, name, true);
  auto next_content_line = [&] {
    while (s.next_line()) {
      if (!s.at_eol()) return true;
    }
    return false;
  };

  if (!next_content_line()) throw IoError("missing OFF header (the file is empty)", name, 1);
  check_header(s, s.token());
  if (s.at_eol()) {
    if (!next_content_line()) s.fail("file ends before the vertex and face counts");
  } else if (s.rest().starts_with("BINARY")) {
    s.fail("binary OFF is unsupported");
  }
  // Some files put the counts on the header line ("OFF 8 6 12"); the edge count is optional and ignored.
  const std::int64_t nv = s.integer("vertex count");
  const std::int64_t nf = s.integer("face count");
  if (nv < 0 || nv >= static_cast<std::int64_t>(max_indices))
    s.fail("bad vertex count " + std::to_string(nv));
  if (nf < 0 || nf >= static_cast<std::int64_t>(max_indices)) s.fail("bad face count " + std::to_string(nf));

  // Reserve no more than the rest of the file can hold, so that a garbled count cannot exhaust memory.
  const std::size_t vertices = static_cast<std::size_t>(nv), faces = static_cast<std::size_t>(nf);
  soup.positions.reserve(std::min(vertices, s.remaining() / 6));
  parsed.vertex_lines.reserve(soup.positions.capacity());
  for (std::size_t i = 0; i < vertices; ++i) {
    if (!next_content_line()) {
      s.fail("file ends after " + std::to_string(i) + " of " + std::to_string(vertices) + " vertices");
    }
    soup.positions.push_back(s.point());
    parsed.vertex_lines.push_back(s.line());
  }

  soup.offsets.reserve(std::min(faces, s.remaining() / 8) + 1);
  parsed.face_lines.reserve(soup.offsets.capacity());
  soup.indices.reserve(std::min(faces * 3, s.remaining() / 2));
  for (std::size_t f = 0; f < faces; ++f) {
    if (!next_content_line()) {
      s.fail("file ends after " + std::to_string(f) + " of " + std::to_string(faces) + " faces");
    }
    const std::int64_t n = s.integer("face size");
    if (n < 3) s.fail(face_size_error(n));
    // Colour values after the indices are ignored.
    for (std::int64_t j = 0; j < n; ++j) {
      const std::int64_t i = s.integer("vertex index");
      if (i < 0 || i >= nv) s.fail(index_error(i, vertices));
      soup.indices.push_back(static_cast<std::uint32_t>(i));
    }
    if (soup.indices.size() > max_indices) s.fail("too many face vertices");
    end_face(parsed, s.line());
  }
  return parsed;
}

}  // namespace io_detail

void write_off(std::ostream& out, const PolygonSoup& soup) {
  io_detail::BlockWriter w(out);
  w.text("OFF\n");
  w.number(std::uint64_t{soup.positions.size()});
  w.put(' ');
  w.number(std::uint64_t{soup.num_faces()});
  w.text(" 0\n");  // the edge count is optional information; readers ignore it
  for (const glm::dvec3& p : soup.positions) w.point_line(p);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) w.counted_face_line(soup.face(f));
  w.flush();
}

}  // namespace dlfl

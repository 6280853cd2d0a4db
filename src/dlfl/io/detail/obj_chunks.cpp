// The chunked OBJ parser (obj_lines.h): counts, prefix sums, then every chunk parsed into its own place.

#include <cstring>
#include <vector>

#include <dlfl/detail/parallel_for.h>
#include <dlfl/io/detail/obj_lines.h>

namespace dlfl::io_detail {

namespace {

// What the first pass finds in a chunk, and (as prefix sums) what comes before it.
struct ChunkCounts {
  std::size_t lines = 0;
  std::size_t vertices = 0;
  std::size_t faces = 0;
};

// Whether the line at `p` (ending at `eol`) is the statement `keyword`: its first token, as
// LineScanner::token reads it, is that one character.
bool is_statement(const char* p, const char* eol, char keyword) {
  while (p != eol && is_blank(*p)) ++p;
  return p != eol && *p == keyword && (p + 1 == eol || is_blank(p[1]));
}

// The first chunk starts with the file, whose byte order mark the scanner skips: so does the count.
ChunkCounts count_chunk(std::string_view chunk, bool first) {
  if (first && chunk.starts_with("\xEF\xBB\xBF")) chunk.remove_prefix(3);
  ChunkCounts counts;
  const char* p = chunk.data();
  const char* const end = p + chunk.size();
  while (p != end) {
    const auto* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    const char* eol = nl ? nl : end;
    ++counts.lines;
    counts.vertices += is_statement(p, eol, 'v');
    counts.faces += is_statement(p, eol, 'f');
    p = nl ? nl + 1 : end;
  }
  return counts;
}

// Thrown inside a chunk when its second pass disagrees with its first (which cannot happen unless the two
// readings of a line differ); the serial parser then decides.
struct Mismatch {};

}  // namespace

ParsedPolygons parse_obj_chunked(std::string_view text, const std::string& name, std::size_t chunk_bytes) {
  // Chunk c is [starts[c], starts[c + 1]): each but the first starts right after a newline, at or after
  // c * chunk_bytes.
  std::vector<std::size_t> starts{0};
  if (chunk_bytes == 0) chunk_bytes = 1;
  for (std::size_t at = chunk_bytes; at < text.size(); at += chunk_bytes) {
    at = std::max(at, starts.back() + 1);
    if (at > text.size()) break;
    const std::size_t nl = text.find('\n', at - 1);
    if (nl == std::string_view::npos || nl + 1 >= text.size()) break;
    starts.push_back(nl + 1);
    at = nl + 1;
  }
  starts.push_back(text.size());
  const std::size_t chunks = starts.size() - 1;
  auto chunk_text = [&](std::size_t c) { return text.substr(starts[c], starts[c + 1] - starts[c]); };

  std::vector<ChunkCounts> before(chunks + 1);
  detail::parallel_chunks(chunks, 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t c = b; c < e; ++c) before[c + 1] = count_chunk(chunk_text(c), c == 0);
  });
  for (std::size_t c = 0; c < chunks; ++c) {
    before[c + 1].lines += before[c].lines;
    before[c + 1].vertices += before[c].vertices;
    before[c + 1].faces += before[c].faces;
  }
  const ChunkCounts total = before[chunks];

  ParsedPolygons parsed;
  parsed.numbering.first_vertex = 1;  // OBJ indices start at 1
  PolygonSoup& soup = parsed.soup;
  soup.positions.resize(total.vertices);
  parsed.vertex_lines.resize(total.vertices);
  soup.offsets.resize(total.faces + 1);
  parsed.face_lines.resize(total.faces);
  // Each chunk's indices go to a list of its own first, as their count is known only once they are read;
  // its faces' offsets are first relative to that list.
  std::vector<std::vector<std::uint32_t>> chunk_indices(chunks);
  try {
    detail::parallel_chunks(chunks, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t c = b; c < e; ++c) {
        const ChunkCounts& at = before[c];
        const ChunkCounts& next = before[c + 1];
        std::size_t v = at.vertices, f = at.faces;
        std::vector<std::uint32_t>& indices = chunk_indices[c];
        LineScanner s(chunk_text(c), name, true, at.lines);
        scan_obj_lines(
            s, static_cast<std::int64_t>(at.vertices), indices,
            [&](const glm::dvec3& p, std::size_t line) {
              if (v == next.vertices) throw Mismatch{};
              soup.positions[v] = p;
              parsed.vertex_lines[v++] = line;
            },
            [&](std::size_t line) {
              if (f == next.faces) throw Mismatch{};
              soup.offsets[f + 1] = static_cast<std::uint32_t>(indices.size());
              parsed.face_lines[f++] = line;
            });
        if (v != next.vertices || f != next.faces) throw Mismatch{};
      }
    });
  } catch (const IoError&) {
    return parse_obj_serial(text, name);  // throws the first error of the file, at its line
  } catch (const Mismatch&) {
    return parse_obj_serial(text, name);
  }

  // Each chunk's indices to their place, and its offsets made absolute.
  std::vector<std::size_t> index_start(chunks + 1, 0);
  for (std::size_t c = 0; c < chunks; ++c) index_start[c + 1] = index_start[c] + chunk_indices[c].size();
  if (index_start[chunks] > max_indices) return parse_obj_serial(text, name);  // "too many face vertices"
  soup.indices.resize(index_start[chunks]);
  detail::parallel_chunks(chunks, 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t c = b; c < e; ++c) {
      std::vector<std::uint32_t>& indices = chunk_indices[c];
      if (!indices.empty()) {
        std::memcpy(soup.indices.data() + index_start[c], indices.data(),
                    indices.size() * sizeof(std::uint32_t));
      }
      const auto shift = static_cast<std::uint32_t>(index_start[c]);
      for (std::size_t f = before[c].faces; f < before[c + 1].faces; ++f) soup.offsets[f + 1] += shift;
      std::vector<std::uint32_t>().swap(indices);
    }
  });
  check_obj_indices(
      soup.num_faces(), [&](std::size_t f) { return soup.face(f); }, parsed.face_lines, soup.positions.size(),
      name);
  return parsed;
}

}  // namespace dlfl::io_detail

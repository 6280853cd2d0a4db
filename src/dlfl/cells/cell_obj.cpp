#include <dlfl/cells/cell_obj.h>

#include <ostream>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/io/detail/text_io.h>

namespace dlfl {

CellComplex parse_cell_obj(std::string_view text, const std::string& name) {
  CellComplex out;
  std::vector<std::size_t> cell_lines;  // for messages about indices checked after the whole file
  std::vector<std::uint32_t> list;
  io_detail::LineScanner s(text, name, true);
  // Negative indices count back from the vertices read so far; positive ones are checked at the end, so a
  // statement may name a vertex defined further down (as in the DLFL OBJ reader).
  auto read_indices = [&] {
    list.clear();
    const auto defined = static_cast<std::int64_t>(out.positions.size());
    while (!s.at_eol()) {
      list.push_back(io_detail::obj_vertex_index(s, defined));
    }
  };
  auto add = [&](std::span<const std::uint32_t> cell) {
    for (std::size_t j = 0; j < cell.size(); ++j) {
      for (std::size_t k = j + 1; k < cell.size(); ++k) {
        if (cell[j] == cell[k])
          s.fail("vertex " + std::to_string(cell[j] + 1) + " is repeated within a cell");
      }
    }
    out.add_cell(cell);
    cell_lines.push_back(s.line());
  };
  while (s.next_line()) {
    const std::string_view keyword = s.token();
    if (keyword == "v") {
      out.positions.push_back(s.point());
    } else if (keyword == "p") {
      read_indices();
      if (list.empty()) s.fail("point statement without a vertex");
      for (std::uint32_t v : list) add(std::span<const std::uint32_t>(&v, 1));
    } else if (keyword == "l") {
      read_indices();
      if (list.size() < 2)
        s.fail("line has " + std::to_string(list.size()) + " vertices; at least 2 are needed");
      for (std::size_t k = 0; k + 1 < list.size(); ++k) add(std::span<const std::uint32_t>(&list[k], 2));
    } else if (keyword == "f") {
      read_indices();
      if (list.size() != 4) {
        s.fail("face has " + std::to_string(list.size()) +
               " vertices; a cell complex (a file with p or l statements) holds quads only: split the "
               "polygons into quads, or drop the p and l statements to load it as a polygon mesh");
      }
      const std::uint32_t quad[4] = {list[0], list[1], list[3], list[2]};  // cyclic -> tensor order
      add(quad);
    }
  }
  io_detail::check_obj_indices(
      out.num_cells(), [&](std::size_t i) { return out.cell(i); }, cell_lines, out.positions.size(), name);
  return out;
}

void write_cell_obj(std::ostream& out, const CellComplex& complex) {
  check_cell_complex(complex);
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    if (complex.dimension(i) == 3) {
      throw IoError("cell " + std::to_string(i) +
                    " is a hexahedron, which OBJ cannot hold; write a .vtk file");
    }
  }
  io_detail::BlockWriter w(out);
  w.text("# dlfl cell complex: p = vertices, l = segments, f = quads\n");
  for (const glm::dvec3& p : complex.positions) {
    w.text("v ");
    w.point_line(p);
  }
  constexpr const char* statement[3] = {"p", "l", "f"};
  constexpr std::uint32_t cyclic[4] = {0, 1, 3, 2};  // tensor -> cyclic order of a quad
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    const auto cell = complex.cell(i);
    w.text(statement[complex.dimension(i)]);
    for (std::size_t k = 0; k < cell.size(); ++k) {
      w.put(' ');
      w.number(std::uint64_t{cell[cell.size() == 4 ? cyclic[k] : k]} + 1);
    }
    w.put('\n');
  }
  w.flush();
}

bool obj_has_cell_statements(std::string_view text) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::size_t k = pos;
    while (k < end && io_detail::is_blank(text[k])) ++k;
    if (k + 1 < end && (text[k] == 'l' || text[k] == 'p') && io_detail::is_blank(text[k + 1])) return true;
    pos = end + 1;
  }
  return false;
}

}  // namespace dlfl

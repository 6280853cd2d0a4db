#include <dlfl/cells/vtk.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <ostream>
#include <system_error>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/detail/text_io.h>

namespace dlfl {
namespace {

bool equals_nocase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
         });
}

const char* cell_type_name(std::int64_t type) {
  switch (type) {
    case 1:
      return "VERTEX";
    case 2:
      return "POLY_VERTEX";
    case 3:
      return "LINE";
    case 4:
      return "POLY_LINE";
    case 5:
      return "TRIANGLE";
    case 6:
      return "TRIANGLE_STRIP";
    case 7:
      return "POLYGON";
    case 8:
      return "PIXEL";
    case 9:
      return "QUAD";
    case 10:
      return "TETRA";
    case 11:
      return "VOXEL";
    case 12:
      return "HEXAHEDRON";
    case 13:
      return "WEDGE";
    case 14:
      return "PYRAMID";
    default:
      return "unknown";
  }
}

// Walks the file: text tokens across lines (ASCII data and keywords) and big-endian binary blocks. Line
// numbers are exact up to the first binary block; after it they are unknown (0), so errors name the element.
class VtkScanner {
 public:
  VtkScanner(std::string_view data, const std::string& name) : data_(data), name_(name) {}

  std::size_t line() const { return lines_known_ ? line_ : 0; }
  [[noreturn]] void fail(const std::string& message, std::size_t at_line) const {
    throw IoError(message, name_, at_line);
  }
  [[noreturn]] void fail(const std::string& message) const { fail(message, line()); }

  /// The rest of the current line, moving to the next; fails at the end of the file.
  std::string_view read_line(const char* what) {
    if (pos_ >= data_.size()) fail(std::string("truncated file: missing ") + what);
    const std::size_t start = pos_;
    const std::size_t nl = data_.find('\n', pos_);
    const std::size_t end = nl == std::string_view::npos ? data_.size() : nl;
    pos_ = nl == std::string_view::npos ? data_.size() : nl + 1;
    token_line_ = line_;
    ++line_;
    std::string_view text = data_.substr(start, end - start);
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t')) {
      text.remove_suffix(1);
    }
    return text;
  }

  /// The next blank-separated token, across lines; empty at the end of the file.
  std::string_view token() {
    while (pos_ < data_.size()) {
      const char c = data_[pos_];
      if (c == '\n') {
        ++line_;
      } else if (!io_detail::is_blank(c)) {
        break;
      }
      ++pos_;
    }
    const std::size_t start = pos_;
    while (pos_ < data_.size() && data_[pos_] != '\n' && !io_detail::is_blank(data_[pos_])) ++pos_;
    token_line_ = line_;
    return data_.substr(start, pos_ - start);
  }
  /// The line of the last token read.
  std::size_t token_line() const { return lines_known_ ? token_line_ : 0; }

  /// The next token as a number of type T. `what` (and `index`, if not npos) name it in errors; the message
  /// is only built on failure, as this runs once per number of the file.
  template <class T>
  T number(const char* what, std::size_t index = std::string::npos) {
    std::string_view t = token();
    auto describe = [&] {
      std::string text = what;
      if (index != std::string::npos) text += ' ' + std::to_string(index);
      return text;
    };
    if (t.empty()) fail("truncated file: missing " + describe());
    if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);  // from_chars rejects a leading '+'
    T value{};
    auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || ptr != t.data() + t.size()) {
      fail("bad " + describe() + " '" + std::string(t) + "'", token_line());
    }
    return value;
  }

  /// Skips to the start of the next line (the binary data after a keyword line); the rest must be blank.
  void end_keyword_line() {
    while (pos_ < data_.size() && data_[pos_] != '\n') {
      if (!io_detail::is_blank(data_[pos_])) fail("unexpected text after the keyword line");
      ++pos_;
    }
    if (pos_ < data_.size()) ++pos_;
    ++line_;
  }
  /// `count` big-endian values of type T; fails if the file ends first.
  template <class T, class Out>
  void binary_block(std::size_t count, const std::string& what, Out&& out) {
    if ((data_.size() - pos_) / sizeof(T) < count) {
      fail("truncated file: " + what + " needs " + std::to_string(count) +
           " binary values, the file ends first");
    }
    lines_known_ = false;
    for (std::size_t i = 0; i < count; ++i) {
      T value;
      std::memcpy(&value, data_.data() + pos_, sizeof(T));
      pos_ += sizeof(T);
      out(i, io_detail::big_endian(value));
    }
  }
  /// Bytes left: a bound on how many values the file can still hold.
  std::size_t remaining() const { return data_.size() - pos_; }

 private:
  std::string_view data_;
  const std::string& name_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t token_line_ = 1;
  bool lines_known_ = true;
};

// The file line of entry i for messages; binary sections keep no lines (empty), which reads as 0.
std::size_t line_of(const std::vector<std::size_t>& lines, std::size_t i) {
  return i < lines.size() ? lines[i] : 0;
}

// What the sections hold before they are turned into cells: the raw lists, and for messages the line of
// each cell's list and of its type (none for binary sections).
struct RawCells {
  std::vector<std::uint64_t> offsets{0};
  std::vector<std::int64_t> connectivity;
  std::vector<std::size_t> cell_lines;
  std::vector<std::int64_t> types;
  std::vector<std::size_t> type_lines;
  std::size_t num_cells() const { return offsets.size() - 1; }
};

// A count read from a section header, bounded by what the file can hold (so a corrupt count cannot make us
// allocate without limit; the bound is loose by a factor of two) and by the 32-bit indices of CellComplex.
std::size_t section_count(VtkScanner& in, const std::string& what, std::size_t bytes_per_item) {
  const auto n = in.number<std::int64_t>(what.c_str());
  if (n < 0) in.fail(what + " is negative", in.token_line());
  if (static_cast<std::uint64_t>(n) > 0xFFFFFFFEull)
    in.fail(what + " exceeds the 32-bit limit", in.token_line());
  if (static_cast<std::size_t>(n) / 2 > in.remaining() / bytes_per_item + 1) {
    in.fail("truncated file: " + what + " is " + std::to_string(n) + " but the file is too short for that",
            in.token_line());
  }
  return static_cast<std::size_t>(n);
}

void read_points(VtkScanner& in, bool binary, CellComplex& out) {
  const std::size_t n = section_count(in, "POINTS count", binary ? 12 : 6);
  const std::string_view type = in.token();
  const bool is_double = equals_nocase(type, "double");
  if (!is_double && !equals_nocase(type, "float")) {
    in.fail("unsupported POINTS type '" + std::string(type) + "' (float or double)", in.token_line());
  }
  out.positions.assign(n, glm::dvec3(0.0));
  auto store = [&](std::size_t i, double value, std::size_t at_line) {
    if (!std::isfinite(value)) {
      in.fail("point " + std::to_string(i / 3) + " has a non-finite coordinate", at_line);
    }
    out.positions[i / 3][int(i % 3)] = value;
  };
  if (!binary) {
    for (std::size_t i = 0; i < 3 * n; ++i) {
      const double value = in.number<double>("coordinate of point", i / 3);
      store(i, value, in.token_line());
    }
    return;
  }
  in.end_keyword_line();
  if (is_double) {
    in.binary_block<double>(3 * n, "POINTS", [&](std::size_t i, double v) { store(i, v, 0); });
  } else {
    in.binary_block<float>(3 * n, "POINTS", [&](std::size_t i, float v) { store(i, double(v), 0); });
  }
}

// Versions before 5: CELLS n size, then per cell its vertex count and its indices (size values in all).
void read_legacy_cells(VtkScanner& in, bool binary, RawCells& raw) {
  const std::size_t n = section_count(in, "CELLS count", binary ? 4 : 2);
  const std::size_t size = section_count(in, "CELLS size", binary ? 4 : 2);
  raw.connectivity.reserve(size);
  raw.offsets.reserve(n + 1);
  if (!binary) {
    raw.cell_lines.reserve(n);
    std::size_t used = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto count = in.number<std::int64_t>("vertex count of cell", i);
      raw.cell_lines.push_back(in.token_line());
      if (count < 0 || used + 1 + std::uint64_t(count) > size) {
        in.fail("cell " + std::to_string(i) + ": vertex count " + std::to_string(count) +
                    " does not fit the CELLS size " + std::to_string(size),
                in.token_line());
      }
      for (std::int64_t k = 0; k < count; ++k) {
        raw.connectivity.push_back(in.number<std::int64_t>("vertex index of cell", i));
      }
      used += 1 + std::size_t(count);
      raw.offsets.push_back(raw.connectivity.size());
    }
    if (used != size)
      in.fail("CELLS size " + std::to_string(size) + " but the lists hold " + std::to_string(used));
    return;
  }
  in.end_keyword_line();
  // One pass over the interleaved counts and indices, straight from the file's bytes.
  std::size_t left = 0;  // indices still to come in the current cell
  in.binary_block<std::int32_t>(size, "CELLS", [&](std::size_t at, std::int32_t v) {
    if (left > 0) {
      raw.connectivity.push_back(v);
      if (--left == 0) raw.offsets.push_back(raw.connectivity.size());
      return;
    }
    const std::size_t i = raw.num_cells();
    if (i == n || v < 0 || at + 1 + std::size_t(v) > size) {
      in.fail("cell " + std::to_string(i) + ": its vertex list does not fit the CELLS count " +
              std::to_string(n) + " and size " + std::to_string(size));
    }
    left = std::size_t(v);
    if (left == 0) raw.offsets.push_back(raw.connectivity.size());
  });
  if (raw.num_cells() != n) {
    in.fail("CELLS count " + std::to_string(n) + " but the lists hold " + std::to_string(raw.num_cells()));
  }
}

// Version 5: CELLS n+1 m, then OFFSETS type (n+1 values) and CONNECTIVITY type (m values).
std::vector<std::int64_t> read_array(VtkScanner& in, bool binary, const char* keyword, std::size_t count,
                                     std::vector<std::size_t>* lines) {
  const std::string_view kw = in.token();
  if (!equals_nocase(kw, keyword)) {
    in.fail(std::string("expected ") + keyword + ", found '" + std::string(kw) + "'", in.token_line());
  }
  const std::string_view type = in.token();
  const bool wide = equals_nocase(type, "vtktypeint64");
  if (!wide && !equals_nocase(type, "vtktypeint32")) {
    in.fail("unsupported " + std::string(keyword) + " type '" + std::string(type) + "'", in.token_line());
  }
  std::vector<std::int64_t> values(count);
  if (!binary) {
    for (std::size_t i = 0; i < count; ++i) {
      values[i] = in.number<std::int64_t>(keyword, i);
      if (lines) lines->push_back(in.token_line());
    }
    return values;
  }
  in.end_keyword_line();
  if (wide) {
    in.binary_block<std::int64_t>(count, keyword, [&](std::size_t i, std::int64_t v) { values[i] = v; });
  } else {
    in.binary_block<std::int32_t>(count, keyword, [&](std::size_t i, std::int32_t v) { values[i] = v; });
  }
  return values;
}

void read_offset_cells(VtkScanner& in, bool binary, RawCells& raw) {
  const std::size_t n_offsets = section_count(in, "CELLS offset count", binary ? 4 : 2);
  const std::size_t size = section_count(in, "CELLS connectivity size", binary ? 4 : 2);
  std::vector<std::size_t> offset_lines;
  const auto offsets = read_array(in, binary, "OFFSETS", n_offsets, &offset_lines);
  raw.connectivity = read_array(in, binary, "CONNECTIVITY", size, nullptr);
  if (n_offsets == 0 || offsets[0] != 0) in.fail("OFFSETS must start with 0");
  raw.offsets.clear();
  for (std::size_t i = 0; i < n_offsets; ++i) {
    if (offsets[i] < (i ? offsets[i - 1] : 0) || std::uint64_t(offsets[i]) > size) {
      in.fail("OFFSETS value " + std::to_string(i) + " (" + std::to_string(offsets[i]) +
                  ") is not between the previous offset and the CONNECTIVITY size",
              line_of(offset_lines, i));
    }
    raw.offsets.push_back(std::uint64_t(offsets[i]));
  }
  if (raw.offsets.back() != size) in.fail("the last OFFSETS value is not the CONNECTIVITY size");
  if (!offset_lines.empty()) raw.cell_lines.assign(offset_lines.begin() + 1, offset_lines.end());
}

void read_cell_types(VtkScanner& in, bool binary, RawCells& raw) {
  const std::size_t n = section_count(in, "CELL_TYPES count", binary ? 4 : 2);
  if (n != raw.num_cells()) {
    in.fail(
        "CELL_TYPES has " + std::to_string(n) + " entries for " + std::to_string(raw.num_cells()) + " cells",
        in.token_line());
  }
  raw.types.resize(n);
  if (!binary) {
    raw.type_lines.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      raw.types[i] = in.number<std::int64_t>("type of cell", i);
      raw.type_lines.push_back(in.token_line());
    }
    return;
  }
  in.end_keyword_line();
  in.binary_block<std::int32_t>(n, "CELL_TYPES", [&](std::size_t i, std::int32_t v) { raw.types[i] = v; });
}

// Turns the raw lists into tensor-ordered cells, checking each against its type and the points.
void emit_cells(const VtkScanner& in, const RawCells& raw, CellComplex& out) {
  const std::size_t nv = out.positions.size();
  out.indices.reserve(raw.connectivity.size());  // exact unless poly cells are split
  out.offsets.reserve(raw.num_cells() + 1);
  std::uint32_t cell[8];
  auto add = [&](std::size_t i, std::size_t size) {
    for (std::size_t j = 0; j < size; ++j) {
      for (std::size_t k = j + 1; k < size; ++k) {
        if (cell[j] == cell[k]) {
          in.fail("cell " + std::to_string(i) + " uses point " + std::to_string(cell[j]) + " twice",
                  line_of(raw.cell_lines, i));
        }
      }
    }
    out.add_cell(std::span<const std::uint32_t>(cell, size));
  };
  for (std::size_t i = 0; i < raw.num_cells(); ++i) {
    const std::int64_t* list = raw.connectivity.data() + raw.offsets[i];
    const std::size_t count = std::size_t(raw.offsets[i + 1] - raw.offsets[i]);
    for (std::size_t k = 0; k < count; ++k) {
      if (list[k] < 0 || std::uint64_t(list[k]) >= nv) {
        in.fail("cell " + std::to_string(i) + " uses point " + std::to_string(list[k]) + " but there are " +
                    std::to_string(nv) + " points",
                line_of(raw.cell_lines, i));
      }
    }
    const std::int64_t type = raw.types[i];
    std::size_t expected = 0;  // 0: any count from `at_least` on
    std::size_t at_least = 1;
    switch (type) {
      case 1:
        expected = 1;
        break;
      case 3:
        expected = 2;
        break;
      case 8:
      case 9:
        expected = 4;
        break;
      case 11:
      case 12:
        expected = 8;
        break;
      case 2:
        at_least = 1;
        break;
      case 4:
        at_least = 2;
        break;
      default:
        in.fail("cell " + std::to_string(i) + " has the unsupported type " + std::to_string(type) + " (" +
                    cell_type_name(type) + "); supported: 1, 2, 3, 4, 8, 9, 11, 12",
                line_of(raw.type_lines, i));
    }
    if (expected ? count != expected : count < at_least) {
      in.fail("cell " + std::to_string(i) + " of type " + cell_type_name(type) + " has " +
                  std::to_string(count) + " points; it needs " + (expected ? "" : "at least ") +
                  std::to_string(expected ? expected : at_least),
              line_of(raw.cell_lines, i));
    }
    auto at = [&](std::size_t k) { return static_cast<std::uint32_t>(list[k]); };
    if (type == 2) {
      for (std::size_t k = 0; k < count; ++k) {
        cell[0] = at(k);
        add(i, 1);
      }
    } else if (type == 4) {
      for (std::size_t k = 0; k + 1 < count; ++k) {
        cell[0] = at(k);
        cell[1] = at(k + 1);
        add(i, 2);
      }
    } else {
      for (std::size_t k = 0; k < count; ++k) {
        cell[k] = type == 9 ? at(vtk_quad_order[k]) : type == 12 ? at(vtk_hexahedron_order[k]) : at(k);
      }
      add(i, count);
    }
  }
}

}  // namespace

CellComplex parse_vtk(std::string_view data, const std::string& name) {
  VtkScanner in(data, name);
  const std::string_view magic = in.read_line("the header line");
  constexpr std::string_view prefix = "# vtk DataFile Version";
  if (!magic.starts_with(prefix)) in.fail("bad header: expected '# vtk DataFile Version x.y'", 1);
  std::string_view version = magic.substr(prefix.size());
  while (!version.empty() && io_detail::is_blank(version.front())) version.remove_prefix(1);
  int major = 0;
  if (std::from_chars(version.data(), version.data() + version.size(), major).ec != std::errc()) {
    in.fail("bad header: no version number", 1);
  }
  in.read_line("the title line");
  const std::string_view encoding = in.read_line("the ASCII or BINARY line");
  const bool binary = equals_nocase(encoding, "BINARY");
  if (!binary && !equals_nocase(encoding, "ASCII")) {
    in.fail("bad header: expected ASCII or BINARY, found '" + std::string(encoding) + "'", 3);
  }
  const std::string_view dataset = in.token();
  if (!equals_nocase(dataset, "DATASET")) {
    in.fail("bad header: expected DATASET, found '" + std::string(dataset) + "'", in.token_line());
  }
  const std::string_view kind = in.token();
  if (!equals_nocase(kind, "UNSTRUCTURED_GRID")) {
    in.fail("unsupported dataset '" + std::string(kind) + "' (only UNSTRUCTURED_GRID)", in.token_line());
  }

  CellComplex out;
  RawCells raw;
  bool have_points = false, have_cells = false, have_types = false;
  for (std::string_view keyword = in.token(); !keyword.empty(); keyword = in.token()) {
    if (equals_nocase(keyword, "POINTS") && !have_points) {
      read_points(in, binary, out);
      have_points = true;
    } else if (equals_nocase(keyword, "CELLS") && !have_cells) {
      if (major >= 5) {
        read_offset_cells(in, binary, raw);
      } else {
        read_legacy_cells(in, binary, raw);
      }
      have_cells = true;
    } else if (equals_nocase(keyword, "CELL_TYPES") && have_cells && !have_types) {
      read_cell_types(in, binary, raw);
      have_types = true;
    } else if (equals_nocase(keyword, "METADATA")) {
      // Information keys that newer writers add after an array, up to an empty line: not needed here.
      in.read_line("the METADATA line");
      while (!in.read_line("the end of METADATA").empty()) {
      }
    } else if (equals_nocase(keyword, "POINT_DATA") || equals_nocase(keyword, "CELL_DATA") ||
               equals_nocase(keyword, "FIELD")) {
      break;  // attributes: not part of a cell complex
    } else {
      in.fail("unexpected section '" + std::string(keyword) + "'", in.token_line());
    }
  }
  if (!have_points) in.fail("truncated file: no POINTS section");
  if (have_cells && !have_types) in.fail("truncated file: CELLS without CELL_TYPES");
  emit_cells(in, raw, out);
  return out;
}

void write_vtk(std::ostream& out, const CellComplex& complex, bool binary) {
  check_cell_complex(complex);
  if (complex.positions.size() > std::size_t(std::numeric_limits<std::int32_t>::max())) {
    throw IoError("VTK: more than 2^31 - 1 points do not fit its 32-bit indices");
  }
  io_detail::BlockWriter w(out);
  auto big_endian = [&](auto value) {
    const auto swapped = io_detail::big_endian(value);
    const char* bytes = reinterpret_cast<const char*>(&swapped);
    for (std::size_t i = 0; i < sizeof(swapped); ++i) w.put(bytes[i]);
  };
  w.text("# vtk DataFile Version 3.0\ndlfl cell complex\n");
  w.text(binary ? "BINARY\n" : "ASCII\n");
  w.text("DATASET UNSTRUCTURED_GRID\nPOINTS ");
  w.number(std::uint64_t{complex.positions.size()});
  w.text(" double\n");
  for (const glm::dvec3& p : complex.positions) {
    if (binary) {
      big_endian(p.x);
      big_endian(p.y);
      big_endian(p.z);
    } else {
      w.point_line(p);
    }
  }
  if (binary) w.put('\n');
  const std::size_t n = complex.num_cells();
  w.text("CELLS ");
  w.number(std::uint64_t{n});
  w.put(' ');
  w.number(std::uint64_t{n + complex.indices.size()});
  w.put('\n');
  for (std::size_t i = 0; i < n; ++i) {
    const auto cell = complex.cell(i);
    const std::uint32_t* order = cell.size() == 4   ? vtk_quad_order
                                 : cell.size() == 8 ? vtk_hexahedron_order
                                                    : nullptr;
    if (binary) {
      big_endian(static_cast<std::int32_t>(cell.size()));
      for (std::size_t k = 0; k < cell.size(); ++k)
        big_endian(static_cast<std::int32_t>(cell[order ? order[k] : k]));
    } else {
      w.number(std::uint64_t{cell.size()});
      for (std::size_t k = 0; k < cell.size(); ++k) {
        w.put(' ');
        w.number(std::uint64_t{cell[order ? order[k] : k]});
      }
      w.put('\n');
    }
  }
  if (binary) w.put('\n');
  w.text("CELL_TYPES ");
  w.number(std::uint64_t{n});
  w.put('\n');
  for (std::size_t i = 0; i < n; ++i) {
    constexpr std::int32_t vtk_type[4] = {1, 3, 9, 12};  // VERTEX, LINE, QUAD, HEXAHEDRON by dimension
    const std::int32_t type = vtk_type[complex.dimension(i)];
    if (binary) {
      big_endian(type);
    } else {
      w.number(std::uint64_t(type));
      w.put('\n');
    }
  }
  if (binary) w.put('\n');
  w.flush();
}

CellComplex read_vtk(const std::filesystem::path& path) {
  return parse_vtk(io_detail::read_file(path), path.string());
}

void write_vtk(const CellComplex& complex, const std::filesystem::path& path, bool binary) {
  check_cell_complex(complex);  // before any file is touched
  write_atomically(
      path, [&](std::ostream& out) { write_vtk(out, complex, binary); }, true);
}

}  // namespace dlfl

// Stanford PLY, ASCII and binary little-endian: vertex x/y/z and the face index lists; everything else
// skipped.

#include <array>
#include <tuple>
#include <utility>
#include <vector>

#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/ply.h>

namespace dlfl {

namespace io_detail {
namespace {

enum class Scalar : std::uint8_t { i8, u8, i16, u16, i32, u32, f32, f64 };

bool parse_scalar(std::string_view s, Scalar& type) {
  struct Name {
    std::string_view name;
    Scalar type;
  };
  static constexpr Name names[] = {
      {"char", Scalar::i8},   {"int8", Scalar::i8},     {"uchar", Scalar::u8},   {"uint8", Scalar::u8},
      {"short", Scalar::i16}, {"int16", Scalar::i16},   {"ushort", Scalar::u16}, {"uint16", Scalar::u16},
      {"int", Scalar::i32},   {"int32", Scalar::i32},   {"uint", Scalar::u32},   {"uint32", Scalar::u32},
      {"float", Scalar::f32}, {"float32", Scalar::f32}, {"double", Scalar::f64}, {"float64", Scalar::f64},
  };
  for (const Name& n : names) {
    if (n.name == s) {
      type = n.type;
      return true;
    }
  }
  return false;
}

// The C++ type of each Scalar, in the enumeration's order: the sizes and the loads below are read from it,
// instead of a switch over the eight types each.
using ScalarTypes = std::tuple<std::int8_t, std::uint8_t, std::int16_t, std::uint16_t, std::int32_t,
                               std::uint32_t, float, double>;
using ScalarIndices = std::make_index_sequence<std::tuple_size_v<ScalarTypes>>;

template <std::size_t... I>
constexpr std::array<std::size_t, sizeof...(I)> scalar_sizes(std::index_sequence<I...>) {
  return {sizeof(std::tuple_element_t<I, ScalarTypes>)...};
}

std::size_t size_of(Scalar t) {
  static constexpr auto sizes = scalar_sizes(ScalarIndices());
  return std::size_t(t) < sizes.size() ? sizes[std::size_t(t)] : 0;
}

bool is_integer(Scalar t) { return t != Scalar::f32 && t != Scalar::f64; }

template <class T>
T load(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return little_endian(value);
}

// A scalar of any PLY type, converted to R (int64 is exact for every integer type PLY has).
template <class R, std::size_t... I>
R load_as(Scalar t, const unsigned char* p, std::index_sequence<I...>) {
  R value = 0;
  // The one I that is t loads; || stops there.
  (void)((std::size_t(t) == I &&
          (value = static_cast<R>(load<std::tuple_element_t<I, ScalarTypes>>(p)), true)) ||
         ...);
  return value;
}
double load_real(Scalar t, const unsigned char* p) { return load_as<double>(t, p, ScalarIndices()); }
// Only called for integer types (checked in the header).
std::int64_t load_integer(Scalar t, const unsigned char* p) {
  return load_as<std::int64_t>(t, p, ScalarIndices());
}

// What a property means to the reader.
enum class Role : std::uint8_t { skip, x, y, z, indices };

struct Property {
  std::string name;
  Scalar type = Scalar::u8;        // the value type, or the item type of a list
  Scalar count_type = Scalar::u8;  // lists only
  bool list = false;
  Role role = Role::skip;
};

struct Element {
  std::string name;
  std::size_t count = 0;
  std::size_t line = 0;
  std::vector<Property> properties;
  bool is_vertex() const { return name == "vertex"; }
  bool is_face() const { return name == "face"; }
};

struct Header {
  bool binary = false;
  std::vector<Element> elements;
  std::size_t num_vertices = 0;
  std::size_t num_faces = 0;
};

Header parse_header(LineScanner& s, const std::string& name) {
  Header h;
  if (!s.next_line() || s.rest() != "ply") s.fail("not a PLY file (the first line must be 'ply')");
  bool have_format = false, have_vertex = false;
  for (;;) {
    if (!s.next_line()) s.fail("the PLY header has no end_header line");
    const std::string_view keyword = s.token();
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      const std::string_view format = s.token();
      if (format == "ascii") {
        h.binary = false;
      } else if (format == "binary_little_endian") {
        h.binary = true;
      } else if (format == "binary_big_endian") {
        s.fail("binary_big_endian PLY is unsupported (use ascii or binary_little_endian)");
      } else {
        s.fail("unknown PLY format '" + std::string(format) + "'");
      }
      if (s.token() != "1.0") s.fail("unsupported PLY version (expected 1.0)");
      have_format = true;
    } else if (keyword == "element") {
      Element e;
      e.name = std::string(s.token());
      e.line = s.line();
      const std::int64_t count = s.integer("element count");
      if (count < 0 || count >= static_cast<std::int64_t>(max_indices)) {
        s.fail("bad count " + std::to_string(count) + " for element '" + e.name + "'");
      }
      e.count = static_cast<std::size_t>(count);
      if (e.is_vertex()) {
        if (have_vertex) s.fail("more than one vertex element");
        have_vertex = true;
        h.num_vertices = e.count;
      }
      if (e.is_face()) h.num_faces += e.count;
      h.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (h.elements.empty()) s.fail("property before any element");
      Element& e = h.elements.back();
      Property p;
      std::string_view type = s.token();
      if (type == "list") {
        p.list = true;
        const std::string_view count_type = s.token();
        if (!parse_scalar(count_type, p.count_type) || !is_integer(p.count_type)) {
          s.fail("bad list count type '" + std::string(count_type) + "'");
        }
        type = s.token();
      }
      if (!parse_scalar(type, p.type)) s.fail("unknown property type '" + std::string(type) + "'");
      p.name = std::string(s.token());
      if (p.name.empty()) s.fail("property without a name");
      // The first property of each meaning wins; a duplicate is skipped.
      auto taken = [&](Role r) {
        return std::any_of(e.properties.begin(), e.properties.end(),
                           [&](const Property& q) { return q.role == r; });
      };
      Role role = Role::skip;
      if (e.is_vertex() && !p.list) {
        if (p.name == "x") role = Role::x;
        if (p.name == "y") role = Role::y;
        if (p.name == "z") role = Role::z;
      }
      if (e.is_face() && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        if (!is_integer(p.type)) s.fail("face vertex indices must have an integer type");
        role = Role::indices;
      }
      if (role != Role::skip && !taken(role)) p.role = role;
      e.properties.push_back(std::move(p));
    } else {
      s.fail("unknown PLY header line '" + std::string(keyword) + "'");
    }
  }
  if (!have_format) s.fail("the PLY header has no format line");
  if (!have_vertex) s.fail("the PLY header has no vertex element");
  for (const Element& e : h.elements) {
    auto has = [&](Role r) {
      return std::any_of(e.properties.begin(), e.properties.end(),
                         [&](const Property& p) { return p.role == r; });
    };
    if (e.is_vertex() && !(has(Role::x) && has(Role::y) && has(Role::z))) {
      throw IoError("the vertex element needs properties x, y and z", name, e.line);
    }
    if (e.is_face() && !has(Role::indices)) {
      throw IoError("the face element has no vertex_indices list", name, e.line);
    }
  }
  return h;
}

std::string element_at(const Element& e, std::size_t i) { return e.name + " " + std::to_string(i); }

void reserve(ParsedPolygons& parsed, const Header& h, std::size_t bytes_left) {
  // No more than the data can hold, so that a garbled count cannot exhaust memory.
  const std::size_t nv = std::min(h.num_vertices, bytes_left / 3), nf = std::min(h.num_faces, bytes_left / 4);
  parsed.soup.positions.reserve(nv);
  parsed.vertex_lines.reserve(nv);
  parsed.soup.offsets.reserve(nf + 1);
  parsed.face_lines.reserve(nf);
  parsed.soup.indices.reserve(std::min(3 * nf, bytes_left / 2));
}

// Refuses, before anything is reserved or read, a header whose element counts the data after it cannot
// hold by far: a binary element needs at least the bytes of its scalars and list counts, an ASCII one a
// character and a separator per value. A count past 16 times that room is a corrupt or hostile header; a file
// merely cut short reads up to its end, where the error names the element. An element without properties
// holds nothing and is skipped, whatever its count.
void check_counts(const Header& h, std::size_t bytes_left, const std::string& name) {
  constexpr std::uint64_t slack = 16;
  std::uint64_t needed = 0;  // bytes (binary) or values (ASCII) of the elements so far
  const std::uint64_t room = slack * (h.binary ? bytes_left : (std::uint64_t{bytes_left} + 1) / 2);
  for (const Element& e : h.elements) {
    std::uint64_t per_element = 0;
    for (const Property& p : e.properties)
      per_element += h.binary ? size_of(p.list ? p.count_type : p.type) : 1;
    if (per_element != 0 && e.count > (room - needed) / per_element) {
      throw IoError("element '" + e.name + "' declares " + std::to_string(e.count) +
                        " entries, far more than the " + std::to_string(bytes_left) +
                        " bytes after the header can hold",
                    name, e.line);
    }
    needed += e.count * per_element;
  }
}

void read_ascii(LineScanner& s, const Header& h, ParsedPolygons& parsed) {
  reserve(parsed, h, s.remaining());
  PolygonSoup& soup = parsed.soup;
  const std::size_t nv = h.num_vertices;
  for (const Element& e : h.elements) {
    if (e.properties.empty()) continue;  // nothing to read, however many it declares
    for (std::size_t i = 0; i < e.count; ++i) {
      // Values are blank-separated and may span lines; each element usually sits on a line of its own.
      auto need = [&] {
        while (s.at_eol()) {
          if (!s.next_line())
            s.fail("the file ends in " + element_at(e, i) + " of " + std::to_string(e.count));
        }
      };
      need();
      const std::size_t line = s.line();
      glm::dvec3 position(0.0);
      for (const Property& p : e.properties) {
        need();
        if (!p.list) {
          switch (p.role) {
            case Role::x:
              position.x = s.number("x coordinate");
              break;
            case Role::y:
              position.y = s.number("y coordinate");
              break;
            case Role::z:
              position.z = s.number("z coordinate");
              break;
            default:
              s.token();
              break;
          }
          continue;
        }
        const std::int64_t n = s.integer("list size");
        if (n < 0) s.fail("negative list size " + std::to_string(n));
        if (p.role != Role::indices) {
          for (std::int64_t j = 0; j < n; ++j) {
            need();
            s.token();
          }
          continue;
        }
        if (n < 3) s.fail(face_size_error(n));
        for (std::int64_t j = 0; j < n; ++j) {
          need();
          const std::int64_t index = s.integer("vertex index");
          if (index < 0 || static_cast<std::uint64_t>(index) >= nv) s.fail(index_error(index, nv));
          soup.indices.push_back(static_cast<std::uint32_t>(index));
        }
        if (soup.indices.size() > max_indices) s.fail("too many face vertices");
        end_face(parsed, line);
      }
      if (e.is_vertex()) {
        soup.positions.push_back(position);
        parsed.vertex_lines.push_back(line);
      }
    }
  }
}

// The fast paths of read_binary for the layouts that writers use (this library's among them): they take
// whole runs of elements at once and stop before the first element that is irregular in any way (cut short,
// a short face, an index out of range, a coordinate not finite), which the general loop then reads, to
// report it. Each returns how many elements it took and moves `p` past them.

// A vertex element of exactly x, y, z, all double or all float.
std::size_t fast_vertices(const Element& e, const unsigned char*& p, std::size_t left,
                          ParsedPolygons& parsed) {
  const auto& props = e.properties;
  if (props.size() != 3 || props[0].role != Role::x || props[1].role != Role::y || props[2].role != Role::z)
    return 0;
  const Scalar type = props[0].type;
  if ((type != Scalar::f64 && type != Scalar::f32) || props[1].type != type || props[2].type != type)
    return 0;
  const std::size_t stride = 3 * size_of(type);
  const std::size_t count = std::min(e.count, left / stride);
  if (count == 0) return 0;  // and an empty vector may have no data pointer, which memcpy must not get
  std::vector<glm::dvec3>& positions = parsed.soup.positions;
  const std::size_t first = positions.size();
  positions.resize(first + count);
  glm::dvec3* out = positions.data() + first;
  if (type == Scalar::f64 && std::endian::native == std::endian::little && sizeof(glm::dvec3) == 24) {
    std::memcpy(static_cast<void*>(out), p, count * stride);  // the file's layout is the vector's
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      const unsigned char* v = p + i * stride;
      out[i] = {load_real(type, v), load_real(type, v + stride / 3), load_real(type, v + 2 * stride / 3)};
    }
  }
  std::size_t taken = 0;
  while (taken < count && std::isfinite(out[taken].x) && std::isfinite(out[taken].y) &&
         std::isfinite(out[taken].z)) {
    ++taken;
  }
  positions.resize(first + taken);
  parsed.vertex_lines.resize(parsed.vertex_lines.size() + taken, 0);
  p += taken * stride;
  return taken;
}

// A face element of exactly the index list, with a uchar or uint count and uint or int indices.
std::size_t fast_faces(const Element& e, const unsigned char*& p, const unsigned char* end, std::size_t nv,
                       ParsedPolygons& parsed) {
  if (e.properties.size() != 1) return 0;
  const Property& prop = e.properties[0];
  if (prop.role != Role::indices || (prop.count_type != Scalar::u8 && prop.count_type != Scalar::u32) ||
      (prop.type != Scalar::u32 && prop.type != Scalar::i32)) {
    return 0;
  }
  const std::size_t count_size = size_of(prop.count_type);
  std::vector<std::uint32_t>& indices = parsed.soup.indices;
  std::size_t taken = 0;
  for (; taken < e.count; ++taken) {
    if (static_cast<std::size_t>(end - p) < count_size) break;
    const std::uint64_t n = prop.count_type == Scalar::u8 ? std::uint64_t{p[0]} : load<std::uint32_t>(p);
    if (n < 3 || static_cast<std::size_t>(end - p - count_size) / 4 < n) break;
    const std::size_t first = indices.size();
    if (first + n > max_indices) break;
    indices.resize(first + n);
    std::uint32_t* out = indices.data() + first;
    std::memcpy(out, p + count_size, n * 4);
    // Both index types pass as unsigned: a negative int is then 2^31 or more, past any vertex count.
    std::uint32_t largest = 0;
    for (std::size_t j = 0; j < n; ++j) {
      out[j] = little_endian(out[j]);
      largest = std::max(largest, out[j]);
    }
    if (largest >= nv || (prop.type == Scalar::i32 && largest > 0x7FFFFFFFu)) {
      indices.resize(first);
      break;
    }
    end_face(parsed, 0);
    p += count_size + n * 4;
  }
  return taken;
}

// Binary data have no lines: errors name the element instead ("face 12") with line 0.
void read_binary(std::string_view data, const Header& h, ParsedPolygons& parsed, const std::string& name) {
  reserve(parsed, h, data.size());
  PolygonSoup& soup = parsed.soup;
  const std::size_t nv = h.num_vertices;
  const auto* p = reinterpret_cast<const unsigned char*>(data.data());
  const auto* const end = p + data.size();
  auto left = [&] { return static_cast<std::size_t>(end - p); };
  for (const Element& e : h.elements) {
    if (e.properties.empty()) continue;  // nothing to read, however many it declares
    std::size_t i = 0;
    if (e.is_vertex()) i = fast_vertices(e, p, left(), parsed);
    if (e.is_face()) i = fast_faces(e, p, end, nv, parsed);
    for (; i < e.count; ++i) {
      auto fail = [&](const std::string& what) { throw IoError(element_at(e, i) + ": " + what, name, 0); };
      const char* const truncated = "the file ends early";
      glm::dvec3 position(0.0);
      for (const Property& prop : e.properties) {
        if (!prop.list) {
          const std::size_t size = size_of(prop.type);
          if (left() < size) fail(truncated);
          switch (prop.role) {
            case Role::x:
              position.x = load_real(prop.type, p);
              break;
            case Role::y:
              position.y = load_real(prop.type, p);
              break;
            case Role::z:
              position.z = load_real(prop.type, p);
              break;
            default:
              break;
          }
          p += size;
          continue;
        }
        const std::size_t count_size = size_of(prop.count_type), item_size = size_of(prop.type);
        if (left() < count_size) fail(truncated);
        const std::int64_t n = load_integer(prop.count_type, p);
        p += count_size;
        if (n < 0) fail("negative list size " + std::to_string(n));
        if (left() / item_size < static_cast<std::uint64_t>(n)) fail(truncated);
        if (prop.role == Role::indices) {
          if (n < 3) fail(face_size_error(n));
          for (std::int64_t j = 0; j < n; ++j) {
            const std::int64_t index = load_integer(prop.type, p + j * item_size);
            if (index < 0 || static_cast<std::uint64_t>(index) >= nv) fail(index_error(index, nv));
            soup.indices.push_back(static_cast<std::uint32_t>(index));
          }
          if (soup.indices.size() > max_indices) fail("too many face vertices");
          end_face(parsed, 0);
        }
        p += static_cast<std::size_t>(n) * item_size;
      }
      if (e.is_vertex()) {
        if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z)) {
          fail("coordinate is not finite");
        }
        soup.positions.push_back(position);
        parsed.vertex_lines.push_back(0);
      }
    }
  }
}

}  // namespace

ParsedPolygons parse_ply_text(std::string_view text, const std::string& name) {
  ParsedPolygons parsed;
  LineScanner s(text, name, false);
  const Header header = parse_header(s, name);
  check_counts(header, text.size() - s.next_offset(), name);
  if (header.binary) {
    read_binary(text.substr(s.next_offset()), header, parsed, name);
  } else {
    read_ascii(s, header, parsed);
  }
  return parsed;
}

}  // namespace io_detail

void write_ply(std::ostream& out, const PolygonSoup& soup, bool binary) {
  std::size_t largest = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) largest = std::max(largest, soup.face(f).size());
  // A uchar count is the common convention; faces of more than 255 vertices need a wider one.
  const bool wide = largest > 255;
  io_detail::BlockWriter w(out);
  w.text(binary ? "ply\nformat binary_little_endian 1.0\n" : "ply\nformat ascii 1.0\n");
  w.text("element vertex ");
  w.number(std::uint64_t{soup.positions.size()});
  w.text("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  w.number(std::uint64_t{soup.num_faces()});
  w.text(wide ? "\nproperty list uint uint vertex_indices\nend_header\n"
              : "\nproperty list uchar uint vertex_indices\nend_header\n");
  if (binary) {
    if (std::endian::native == std::endian::little && sizeof(glm::dvec3) == 24) {
      // The vertex block is the positions' memory as it is.
      w.text(
          {reinterpret_cast<const char*>(soup.positions.data()), soup.positions.size() * sizeof(glm::dvec3)});
    } else {
      for (const glm::dvec3& p : soup.positions) {
        w.binary(p.x);
        w.binary(p.y);
        w.binary(p.z);
      }
    }
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      const auto face = soup.face(f);
      if (wide) {
        w.binary(static_cast<std::uint32_t>(face.size()));
      } else {
        w.binary(static_cast<std::uint8_t>(face.size()));
      }
      w.binary_values(face);
    }
  } else {
    for (const glm::dvec3& p : soup.positions) w.point_line(p);
    for (std::size_t f = 0; f < soup.num_faces(); ++f) w.counted_face_line(soup.face(f));
  }
  w.flush();
}

}  // namespace dlfl

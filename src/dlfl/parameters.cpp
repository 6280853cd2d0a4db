#include <dlfl/parameters.h>

#include <charconv>
#include <cmath>
#include <iterator>
#include <optional>

#include <dlfl/detail/enum_names.h>
#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/mesh.h>

namespace dlfl {

std::string_view to_string(ParamType type) {
  static constexpr const char* names[] = {"boolean", "integer", "number", "text",     "point", "vertex",
                                          "edge",    "face",    "corner", "vertices", "edges", "faces",
                                          "corners", "numbers", "points", "mesh",     "params"};
  static_assert(std::size(names) == std::size_t(ParamType::params) + 1, "a name per enumerator, in order");
  return detail::name_at(type, names, "?");
}

namespace {
// What each ParamType holds, in the enumeration's order: the type of its items (itself for a single value),
// and what a message says a value of it must be.
using P = ParamType;
constexpr ParamType item_types[] = {P::boolean, P::integer, P::number, P::text,   P::point, P::vertex,
                                    P::edge,    P::face,    P::corner, P::vertex, P::edge,  P::face,
                                    P::corner,  P::number,  P::point,  P::mesh,   P::params};
constexpr const char* expected_values[] = {
    // single values
    "true or false", "a whole number", "a number", "text", "a point x,y,z",
    // one handle: "a edge" as the messages have always said
    "a vertex handle (its number)", "a edge handle (its number)", "a face handle (its number)",
    "a corner handle (its number)",
    // lists
    "a list of vertex handles a,b,c", "a list of edge handles a,b,c", "a list of face handles a,b,c",
    "a list of corner handles a,b,c", "a list of numbers a,b,c", "a list of points x,y,z;x,y,z",
    // whole objects
    "a mesh", "a parameter set"};
static_assert(std::size(item_types) == std::size_t(ParamType::params) + 1 &&
                  std::size(expected_values) == std::size(item_types),
              "an entry per enumerator, in order");

// The list element types and the single-value type each list holds.
ParamType element_type(ParamType t) {
  return std::size_t(t) < std::size(item_types) ? item_types[std::size_t(t)] : t;
}

bool is_single_handle(ParamType t) {
  return t == ParamType::vertex || t == ParamType::edge || t == ParamType::face || t == ParamType::corner;
}
}  // namespace

// ---- Value
// ---------------------------------------------------------------------------------------------------

Value::Value(Params params) : v_(std::make_shared<const Params>(std::move(params))) {}

namespace {
const char* kind_name(Value::Kind k) {
  static constexpr const char* names[] = {
      "nothing",        "a boolean",          "an integer",        "a number",         "text",
      "a point",        "a list of integers", "a list of numbers", "a list of points", "a mesh",
      "a parameter set"};
  static_assert(std::size(names) == std::size_t(Value::Kind::params) + 1, "a name per enumerator, in order");
  return detail::name_at(k, names, "?");
}

template <class T, class V>
const T& held(const V& v, Value::Kind actual, Value::Kind wanted) {
  if (const T* p = std::get_if<T>(&v)) return *p;
  throw InvalidArgument(std::string("expected ") + kind_name(wanted) + ", got " + kind_name(actual));
}

// The `text` of each item, `separator`-separated.
template <class List, class Text>
std::string joined(const List& items, const char* separator, Text text) {
  std::string list;
  for (const auto& item : items) {
    if (!list.empty()) list += separator;
    list += text(item);
  }
  return list;
}

std::string point_text(const glm::dvec3& p) {
  return format_number(p.x) + "," + format_number(p.y) + "," + format_number(p.z);
}
}  // namespace

bool Value::as_bool() const { return held<bool>(v_, kind(), Kind::boolean); }
std::int64_t Value::as_integer() const { return held<std::int64_t>(v_, kind(), Kind::integer); }
double Value::as_number() const {
  if (const auto* i = std::get_if<std::int64_t>(&v_)) return static_cast<double>(*i);
  return held<double>(v_, kind(), Kind::number);
}
const std::string& Value::as_text() const { return held<std::string>(v_, kind(), Kind::text); }
const glm::dvec3& Value::as_point() const { return held<glm::dvec3>(v_, kind(), Kind::point); }
const std::vector<std::int64_t>& Value::as_integers() const {
  return held<std::vector<std::int64_t>>(v_, kind(), Kind::integers);
}
const std::vector<double>& Value::as_numbers() const {
  return held<std::vector<double>>(v_, kind(), Kind::numbers);
}
const std::vector<glm::dvec3>& Value::as_points() const {
  return held<std::vector<glm::dvec3>>(v_, kind(), Kind::points);
}
const Mesh& Value::as_mesh() const { return *mesh_pointer(); }
const std::shared_ptr<const Mesh>& Value::mesh_pointer() const {
  const auto& p = held<std::shared_ptr<const Mesh>>(v_, kind(), Kind::mesh);
  if (!p) throw InvalidArgument("expected a mesh, got none");
  return p;
}
const Params& Value::as_params() const {
  const auto& p = held<std::shared_ptr<const Params>>(v_, kind(), Kind::params);
  if (!p) throw InvalidArgument("expected a parameter set, got none");
  return *p;
}

std::string Value::to_text() const {
  switch (kind()) {
    case Kind::empty:
      return "";
    case Kind::boolean:
      return as_bool() ? "true" : "false";
    case Kind::integer:
      return std::to_string(as_integer());
    case Kind::number:
      return format_number(as_number());
    case Kind::text:
      return as_text();
    case Kind::point:
      return point_text(as_point());
    case Kind::integers:
      return joined(as_integers(), ",", [](std::int64_t i) { return std::to_string(i); });
    case Kind::numbers:
      return joined(as_numbers(), ",", format_number);
    case Kind::points:
      return joined(as_points(), ";", point_text);
    case Kind::mesh:
      return "[mesh]";
    case Kind::params:
      return "{" +
             joined(as_params(), " ", [](const auto& p) { return p.first + "=" + p.second.to_text(); }) + "}";
  }
  return "";
}

bool operator==(const Value& a, const Value& b) {
  if (a.kind() != b.kind()) return false;
  if (a.kind() == Value::Kind::params) return a.as_params() == b.as_params();
  return a.v_ == b.v_;  // meshes compare by pointer: identity
}

// ---- Params
// --------------------------------------------------------------------------------------------------

const Value& Params::get(std::string_view name) const {
  auto it = find(name);
  if (it == end()) throw ParameterError("parameter " + std::string(name) + " is missing", std::string(name));
  return it->second;
}

namespace {
template <class F>
decltype(auto) typed(const Params& p, std::string_view name, F&& read) {
  const Value& v = p.get(name);
  try {
    return read(v);
  } catch (const ParameterError&) {
    throw;
  } catch (const InvalidArgument& e) {
    throw ParameterError("parameter " + std::string(name) + ": " + e.what(), std::string(name));
  }
}
}  // namespace

bool Params::boolean(std::string_view name) const {
  return typed(*this, name, [](const Value& v) { return v.as_bool(); });
}
std::int64_t Params::integer(std::string_view name) const {
  return typed(*this, name, [](const Value& v) { return v.as_integer(); });
}
double Params::number(std::string_view name) const {
  return typed(*this, name, [](const Value& v) { return v.as_number(); });
}
const std::string& Params::text(std::string_view name) const {
  return typed(*this, name, [](const Value& v) -> const std::string& { return v.as_text(); });
}
const glm::dvec3& Params::point(std::string_view name) const {
  return typed(*this, name, [](const Value& v) -> const glm::dvec3& { return v.as_point(); });
}

// ---- ParamSpec
// -----------------------------------------------------------------------------------------------

ParamSpec& ParamSpec::range(double lo, double hi, bool lo_open, bool hi_open) {
  min = lo;
  max = hi;
  min_open = lo_open;
  max_open = hi_open;
  return *this;
}

ParamSpec& ParamSpec::optional(std::string how_chosen) {
  is_optional = true;
  default_doc = std::move(how_chosen);
  return *this;
}

ParamSpec& ParamSpec::before_version3(Value meaning) {
  in_old_logs = std::move(meaning);
  return *this;
}

ParamSpec& ParamSpec::one_of(std::vector<std::string> words) {
  keywords = std::move(words);
  return *this;
}

bool ParamSpec::is_handle() const { return is_single_handle(element_type(type)); }

std::string ParamSpec::range_text() const {
  if (std::isinf(min) && std::isinf(max)) return "";
  return std::string(min_open || std::isinf(min) ? "(" : "[") + format_number(min) + ", " +
         format_number(max) + (max_open || std::isinf(max) ? ")" : "]");
}

ParamSpec param(std::string name, ParamType type, std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = type;
  s.doc = std::move(doc);
  return s;
}

ParamSpec param(std::string name, ParamType type, Value default_value, std::string doc) {
  ParamSpec s = param(std::move(name), type, std::move(doc));
  s.default_value = std::move(default_value);
  return s;
}

// ---- conversion and checks
// -----------------------------------------------------------------------------------

namespace {

[[noreturn]] void bad(std::string_view context, const ParamSpec& spec, const std::string& what) {
  throw ParameterError(std::string(context) + ": parameter " + spec.name + " " + what, spec.name);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// A double or an int64 that is the whole text, blanks around it and a leading '+' allowed.
template <class T>
bool read_scalar(std::string_view text, T& out) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return !text.empty() && ec == std::errc() && ptr == end;
}
bool read_number(std::string_view text, double& out) { return read_scalar(text, out); }
bool read_integer(std::string_view text, std::int64_t& out) { return read_scalar(text, out); }

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  if (trim(text).empty()) return parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(sep, start);
    parts.push_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return parts;
}

// Well-formed UTF-8 (Unicode table 3-7: no overlong forms, surrogates or code points past U+10FFFF). Text
// values go into operation logs, and JSON holds nothing else.
bool is_utf8(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto b = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;              // continuation bytes
    unsigned lo = 0x80, hi = 0xBF;  // the allowed range of the first continuation byte
    if (b < 0x80) {
      ++i;
      continue;
    } else if (b >= 0xC2 && b <= 0xDF) {
      n = 1;
    } else if (b >= 0xE0 && b <= 0xEF) {
      n = 2;
      if (b == 0xE0) lo = 0xA0;
      if (b == 0xED) hi = 0x9F;
    } else if (b >= 0xF0 && b <= 0xF4) {
      n = 3;
      if (b == 0xF0) lo = 0x90;
      if (b == 0xF4) hi = 0x8F;
    } else {
      return false;
    }
    if (s.size() - i <= n) return false;
    for (std::size_t k = 1; k <= n; ++k) {
      const auto c = static_cast<unsigned char>(s[i + k]);
      if (c < (k == 1 ? lo : 0x80) || c > (k == 1 ? hi : 0xBF)) return false;
    }
    i += n + 1;
  }
  return true;
}

bool whole(double d) { return std::isfinite(d) && d == std::floor(d) && std::abs(d) <= 0x1.0p53; }

// x,y,z, the whole text.
bool read_point(std::string_view text, glm::dvec3& out) {
  const auto parts = split(text, ',');
  if (parts.size() != 3) return false;
  for (int i = 0; i < 3; ++i) {
    if (!read_number(parts[i], out[i])) return false;
  }
  return true;
}

// The items of a `separator`-separated list, each read by `read`; nothing if one does not read.
template <class T, class Read>
std::optional<Value> read_list(std::string_view text, char separator, Read read) {
  std::vector<T> out;
  for (auto part : split(text, separator)) {
    T item{};
    if (!read(part, item)) return std::nullopt;
    out.push_back(item);
  }
  return Value(std::move(out));
}

std::string expected(ParamType t) { return detail::name_at(t, expected_values, "?"); }

std::string shown(const Value& v) {
  const std::string t = v.to_text();
  return v.kind() == Value::Kind::text ? "'" + t + "'" : t;
}

// The value as the declared type, or nothing if it cannot be read as one.
std::optional<Value> convert(ParamType type, const Value& v) {
  using K = Value::Kind;
  const K k = v.kind();
  const bool text = k == K::text;
  switch (type) {
    case ParamType::boolean:
      if (k == K::boolean) return v;
      if (k == K::integer && (v.as_integer() == 0 || v.as_integer() == 1)) return Value(v.as_integer() == 1);
      if (k == K::number && (v.as_number() == 0.0 || v.as_number() == 1.0))
        return Value(v.as_number() == 1.0);
      if (text) {
        const auto t = trim(v.as_text());
        if (t == "true" || t == "1") return Value(true);
        if (t == "false" || t == "0") return Value(false);
      }
      return std::nullopt;
    case ParamType::integer:
    case ParamType::vertex:
    case ParamType::edge:
    case ParamType::face:
    case ParamType::corner: {
      std::int64_t i = 0;
      if (k == K::integer) {
        i = v.as_integer();
      } else if (k == K::number && whole(v.as_number())) {
        i = static_cast<std::int64_t>(v.as_number());
      } else if (!(text && read_integer(v.as_text(), i))) {
        return std::nullopt;
      }
      return Value(i);
    }
    case ParamType::number: {
      double d = 0;
      if (k == K::number || k == K::integer) return Value(v.as_number());
      if (text && read_number(v.as_text(), d)) return Value(d);
      return std::nullopt;
    }
    case ParamType::text:
      if (text) return v;
      return std::nullopt;
    case ParamType::point: {
      if (k == K::point) return v;
      if (k == K::numbers && v.as_numbers().size() == 3) {
        const auto& n = v.as_numbers();
        return Value(glm::dvec3(n[0], n[1], n[2]));
      }
      if (k == K::integers && v.as_integers().size() == 3) {
        const auto& n = v.as_integers();
        return Value(glm::dvec3(double(n[0]), double(n[1]), double(n[2])));
      }
      glm::dvec3 p(0.0);
      if (text && read_point(v.as_text(), p)) return Value(p);
      return std::nullopt;
    }
    case ParamType::vertices:
    case ParamType::edges:
    case ParamType::faces:
    case ParamType::corners: {
      if (k == K::integers) return v;
      std::vector<std::int64_t> out;
      if (k == K::integer) return Value(std::vector<std::int64_t>{v.as_integer()});
      if (k == K::numbers) {
        for (double d : v.as_numbers()) {
          if (!whole(d)) return std::nullopt;
          out.push_back(static_cast<std::int64_t>(d));
        }
        return Value(std::move(out));
      }
      if (text) return read_list<std::int64_t>(v.as_text(), ',', read_integer);
      return std::nullopt;
    }
    case ParamType::numbers: {
      if (k == K::numbers) return v;
      std::vector<double> out;
      if (k == K::integers) {
        for (auto i : v.as_integers()) out.push_back(double(i));
        return Value(std::move(out));
      }
      if (k == K::number || k == K::integer) return Value(std::vector<double>{v.as_number()});
      if (text) return read_list<double>(v.as_text(), ',', read_number);
      return std::nullopt;
    }
    case ParamType::points: {
      if (k == K::points) return v;
      if (k == K::point) return Value(std::vector<glm::dvec3>{v.as_point()});
      if (text) return read_list<glm::dvec3>(v.as_text(), ';', read_point);
      return std::nullopt;
    }
    case ParamType::mesh:
      if (k == K::mesh) return v;
      return std::nullopt;
    case ParamType::params:
      if (k == K::params) return v;
      return std::nullopt;
  }
  return std::nullopt;
}

bool in_range(const ParamSpec& s, double d) {
  if (std::isnan(d)) return false;
  if (s.min_open ? !(d > s.min) : !(d >= s.min)) return false;
  if (s.max_open ? !(d < s.max) : !(d <= s.max)) return false;
  return true;
}

template <class H>
void require_alive(std::string_view context, const ParamSpec& spec, const Mesh& mesh, std::int64_t i) {
  const H h(static_cast<std::uint32_t>(i));
  if (!mesh.is_alive(h)) {
    bad(context, spec,
        "= " + std::to_string(i) + ": " + to_string(h) + " does not exist (removed or never created)");
  }
}

void check_handle(std::string_view context, const ParamSpec& spec, const Mesh* mesh, std::int64_t i) {
  if (i < 0 || i >= std::int64_t(VertexId::invalid_index)) {
    bad(context, spec,
        "= " + std::to_string(i) + " is not a " + std::string(to_string(element_type(spec.type))) +
            " handle");
  }
  if (!mesh) return;
  switch (element_type(spec.type)) {
    case ParamType::vertex:
      return require_alive<VertexId>(context, spec, *mesh, i);
    case ParamType::edge:
      return require_alive<EdgeId>(context, spec, *mesh, i);
    case ParamType::face:
      return require_alive<FaceId>(context, spec, *mesh, i);
    case ParamType::corner:
      return require_alive<CornerId>(context, spec, *mesh, i);
    default:
      return;
  }
}

void check_number(std::string_view context, const ParamSpec& spec, double d) {
  if (!std::isfinite(d)) bad(context, spec, "= " + format_number(d) + " is not finite");
  if (!in_range(spec, d)) bad(context, spec, "= " + format_number(d) + " is outside " + spec.range_text());
}

Value checked(std::string_view context, const ParamSpec& spec, const Value& given, const Mesh* mesh) {
  // A keyword stands in for a value of any type.
  if (spec.type != ParamType::text && given.kind() == Value::Kind::text) {
    for (const auto& k : spec.keywords) {
      if (trim(given.as_text()) == k) return Value(k);
    }
  }
  auto v = convert(spec.type, given);
  if (!v) {
    std::string want = expected(spec.type);
    for (const auto& k : spec.keywords) want += " or '" + k + "'";
    bad(context, spec, "must be " + want + ", not " + shown(given));
  }
  switch (spec.type) {
    case ParamType::integer:
      check_number(context, spec, double(v->as_integer()));
      break;
    case ParamType::number:
      check_number(context, spec, v->as_number());
      break;
    case ParamType::numbers:
      for (double d : v->as_numbers()) check_number(context, spec, d);
      break;
    case ParamType::point:
      for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(v->as_point()[i])) bad(context, spec, "= " + v->to_text() + " is not finite");
      }
      break;
    case ParamType::points:
      for (const auto& p : v->as_points()) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
          bad(context, spec, "has a point that is not finite");
        }
      }
      break;
    case ParamType::text:
      if (!is_utf8(v->as_text())) bad(context, spec, "is not valid UTF-8 text");
      if (!spec.keywords.empty()) {
        bool known = false;
        for (const auto& k : spec.keywords) known = known || v->as_text() == k;
        if (!known) {
          std::string list;
          for (const auto& k : spec.keywords) list += (list.empty() ? "" : ", ") + k;
          bad(context, spec, "must be one of " + list + ", not '" + v->as_text() + "'");
        }
      }
      break;
    default:
      if (is_single_handle(spec.type)) {
        check_handle(context, spec, mesh, v->as_integer());
      } else if (spec.is_handle()) {
        for (auto i : v->as_integers()) check_handle(context, spec, mesh, i);
      }
  }
  return *v;
}

}  // namespace

Params resolve_params(std::string_view context, std::span<const ParamSpec> specs, const Params& given,
                      const Mesh* mesh) {
  for (const auto& [name, value] : given) {
    bool known = false;
    for (const auto& s : specs) known = known || s.name == name;
    if (!known) {
      std::vector<std::string> names;
      for (const auto& s : specs) names.push_back(s.name);
      const std::string suggestion = closest_name(name, names);
      std::string message = std::string(context) + ": unknown parameter '" + name + "' (";
      if (!suggestion.empty()) message += "did you mean '" + suggestion + "'?; ";
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      message += list.empty() ? std::string("it takes none") : "known: " + list;
      throw ParameterError(message + ")", name);
    }
  }
  Params full;
  for (const auto& spec : specs) {
    auto it = given.find(spec.name);
    if (it != given.end() && !it->second.empty()) {
      full[spec.name] = checked(context, spec, it->second, mesh);
    } else if (!spec.default_value.empty()) {
      full[spec.name] = spec.default_value;
    } else if (!spec.is_optional) {
      throw ParameterError(std::string(context) + ": parameter " + spec.name + " is missing", spec.name);
    }
  }
  return full;
}

Value parse_value(std::string_view context, const ParamSpec& spec, std::string_view text) {
  if (spec.type != ParamType::text) {
    for (const auto& k : spec.keywords) {
      if (trim(text) == k) return Value(k);
    }
  }
  auto v = convert(spec.type, Value(std::string(text)));
  if (!v) bad(context, spec, "must be " + expected(spec.type) + ", not '" + std::string(text) + "'");
  return *v;
}

std::pair<std::string, Value> parse_assignment(std::string_view text) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0) {
    throw ParameterError("'" + std::string(text) + "' is not of the form name=value", std::string(text));
  }
  return {std::string(text.substr(0, eq)), Value(std::string(text.substr(eq + 1)))};
}

}  // namespace dlfl

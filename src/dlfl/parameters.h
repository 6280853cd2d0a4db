#pragma once
// Named, typed parameters: the values that operations and schemes take, and the declarations (name, type,
// default, allowed range, one line of documentation) that generic code checks them against. Each operation
// and each scheme declares its parameters once, next to its implementation; the editor, the operation log
// and the command line all read those declarations.

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <dlfl/handles.h>

namespace dlfl {

class Mesh;
struct Params;

/// The declared type of a parameter.
enum class ParamType : std::uint8_t {
  boolean,   ///< true or false
  integer,   ///< a whole number
  number,    ///< a double
  text,      ///< a string (with `keywords`: one of them)
  point,     ///< x, y, z
  vertex,    ///< one handle, by its index
  edge,      ///< one handle, by its index
  face,      ///< one handle, by its index
  corner,    ///< one handle, by its index
  vertices,  ///< a list of handles
  edges,     ///< a list of handles
  faces,     ///< a list of handles
  corners,   ///< a list of handles
  numbers,   ///< a list of doubles
  points,    ///< a list of points
  mesh,      ///< a whole mesh (the load and mesh operations)
  params,    ///< a nested parameter set (the scheme parameters of subdivide)
};

/// The type's name as listings and logs spell it: "number", "corner", "points", ...
std::string_view to_string(ParamType type);

/// One parameter value. Converting constructors make call sites read naturally: `{"t", 1}`, `{"t", 0.5}`,
/// `{"corner1", CornerId(4)}`, `{"center", glm::dvec3(0, 0, 1)}`, `{"pattern", "H4P4"}`. Handles are held as
/// their index. A default-constructed Value is empty ("not given").
///
/// Values that come from a command line are text; `resolve_params` converts them by the declared type.
class Value {
 public:
  enum class Kind : std::uint8_t {
    empty,
    boolean,
    integer,
    number,
    text,
    point,
    integers,
    numbers,
    points,
    mesh,
    params
  };

  Value() = default;
  Value(bool b) : v_(b) {}
  Value(int i) : v_(std::int64_t(i)) {}
  Value(long i) : v_(std::int64_t(i)) {}
  Value(long long i) : v_(std::int64_t(i)) {}
  Value(unsigned i) : v_(std::int64_t(i)) {}
  Value(unsigned long i) : v_(std::int64_t(i)) {}
  Value(unsigned long long i) : v_(std::int64_t(i)) {}
  Value(double d) : v_(d) {}
  Value(const char* s) : v_(std::string(s)) {}
  Value(std::string s) : v_(std::move(s)) {}
  Value(std::string_view s) : v_(std::string(s)) {}
  Value(const glm::dvec3& p) : v_(p) {}
  /// A handle is stored as its index; an invalid handle as -1.
  template <class Tag>
  Value(Handle<Tag> h) : v_(h.valid() ? std::int64_t(h.index()) : std::int64_t(-1)) {}
  Value(std::vector<std::int64_t> list) : v_(std::move(list)) {}
  Value(std::vector<double> list) : v_(std::move(list)) {}
  Value(std::vector<glm::dvec3> list) : v_(std::move(list)) {}
  template <class Tag>
  Value(const std::vector<Handle<Tag>>& handles) : v_(handle_indices(handles)) {}
  Value(std::shared_ptr<const Mesh> mesh) : v_(std::move(mesh)) {}
  Value(Params params);

  Kind kind() const { return static_cast<Kind>(v_.index()); }
  bool empty() const { return kind() == Kind::empty; }

  // Typed access. Each throws InvalidArgument when the value holds another kind (an integer reads as a
  // number; nothing else converts: `resolve_params` does the conversions).
  bool as_bool() const;
  std::int64_t as_integer() const;
  double as_number() const;
  const std::string& as_text() const;
  const glm::dvec3& as_point() const;
  const std::vector<std::int64_t>& as_integers() const;
  const std::vector<double>& as_numbers() const;
  const std::vector<glm::dvec3>& as_points() const;
  const Mesh& as_mesh() const;
  /// The mesh as shared, so that keeping it (in an editor's log) needs no copy.
  const std::shared_ptr<const Mesh>& mesh_pointer() const;
  const Params& as_params() const;
  /// A handle from an integer value: H(index), or the invalid handle for -1.
  template <class H>
  H as_handle() const {
    const std::int64_t i = as_integer();
    return i < 0 ? H() : H(static_cast<std::uint32_t>(i));
  }
  template <class H>
  std::vector<H> as_handles() const {
    std::vector<H> out;
    for (std::int64_t i : as_integers()) out.push_back(i < 0 ? H() : H(static_cast<std::uint32_t>(i)));
    return out;
  }

  /// The value as a person would type it on a command line: "0.5", "true", "1,2,3", "[mesh]"; numbers in
  /// shortest round-trip form.
  std::string to_text() const;

  /// Equal kinds and equal contents (meshes by identity, parameter sets by value).
  friend bool operator==(const Value& a, const Value& b);

 private:
  template <class Tag>
  static std::vector<std::int64_t> handle_indices(const std::vector<Handle<Tag>>& handles) {
    std::vector<std::int64_t> out;
    out.reserve(handles.size());
    for (auto h : handles) out.push_back(h.valid() ? std::int64_t(h.index()) : std::int64_t(-1));
    return out;
  }
  std::variant<std::monostate, bool, std::int64_t, double, std::string, glm::dvec3, std::vector<std::int64_t>,
               std::vector<double>, std::vector<glm::dvec3>, std::shared_ptr<const Mesh>,
               std::shared_ptr<const Params>>
      v_;
};

/// Parameter values by name, sorted. Typed getters throw ParameterError naming the parameter when it is
/// missing or of another kind.
struct Params : std::map<std::string, Value, std::less<>> {
  using map::map;

  bool has(std::string_view name) const { return find(name) != end(); }
  const Value& get(std::string_view name) const;
  bool boolean(std::string_view name) const;
  std::int64_t integer(std::string_view name) const;
  double number(std::string_view name) const;
  const std::string& text(std::string_view name) const;
  const glm::dvec3& point(std::string_view name) const;
  template <class H>
  H handle(std::string_view name) const {
    return get(name).as_handle<H>();
  }
  template <class H>
  std::vector<H> handles(std::string_view name) const {
    return get(name).as_handles<H>();
  }
};

/// The declaration of one parameter. Build one with `param(...)` and refine it with the chained setters:
///
///     param("t", ParamType::number, 0.5, "the point (1 - t) v_m + t v_m+1 on each edge").in(0, 1)
///     param("a", ParamType::number, "a constant tension").optional().in_open(0, 1)
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::number;
  /// One line for listings and help.
  std::string doc;
  /// Used when the parameter is not given. Empty: the parameter is required, unless `is_optional`.
  Value default_value;
  /// May be left out with no default: the operation then chooses, as `default_doc` says.
  bool is_optional = false;
  /// How a computed default is chosen, for listings ("the edge midpoint"). Empty for plain defaults.
  std::string default_doc;
  /// The allowed range of an integer or number (of each element of a list of numbers). Open ends are
  /// exclusive.
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;
  /// For text: the allowed values, when not empty. For other types: words accepted in place of a value (the
  /// keyword "centroid" for a point), kept as text.
  std::vector<std::string> keywords;
  /// What a log written before this parameter existed (oplog version 1 or 2, which lacks the field) means:
  /// filled in when such a log is replayed. Empty: the default, as for any parameter left out.
  Value in_old_logs;

  ParamSpec& in(double lo, double hi) { return range(lo, hi, false, false); }
  ParamSpec& in_open(double lo, double hi) { return range(lo, hi, true, true); }
  ParamSpec& range(double lo, double hi, bool lo_open, bool hi_open);
  ParamSpec& at_least(double lo) { return range(lo, max, false, max_open); }
  ParamSpec& optional(std::string how_chosen = {});
  ParamSpec& one_of(std::vector<std::string> words);
  /// Sets `in_old_logs`.
  ParamSpec& before_version3(Value meaning);
  /// True for the types whose values are handles (one or a list).
  bool is_handle() const;
  /// The range as text, "[0, 1]", "(0, 1)", "[1, inf)"; empty if unbounded.
  std::string range_text() const;
};

/// A required parameter.
ParamSpec param(std::string name, ParamType type, std::string doc);
/// A parameter with a default.
ParamSpec param(std::string name, ParamType type, Value default_value, std::string doc);

/// Checks `given` against the declarations and returns the full set: every given name known, every value
/// converted to its declared type, in range and, for handles, alive in `mesh` (when a mesh is given); every
/// missing parameter filled in from its default (optional ones without a default stay absent). Conversions:
/// text is parsed by type (a point "x,y,z", a list "a,b,c", a list of points "x,y,z;x,y,z", a boolean
/// "true"/"false"/"1"/"0"); an integer is a number; a whole number is an integer or a handle; 0 and 1 are
/// booleans; three numbers are a point. `context` names the operation or scheme in messages. Throws
/// ParameterError naming the parameter ("honeycomb: parameter t = 2 is outside [0, 1]", "insert_edge:
/// unknown parameter 'corner3' (did you mean 'corner1'?; known: corner1, corner2)").
Params resolve_params(std::string_view context, std::span<const ParamSpec> specs, const Params& given,
                      const Mesh* mesh = nullptr);

/// The value of `text` read as the declared type (see `resolve_params`), without range checks. Throws
/// ParameterError naming `spec.name`.
Value parse_value(std::string_view context, const ParamSpec& spec, std::string_view text);

/// Splits "name=value" as typed on a command line; the value stays text until resolved against a
/// declaration. Throws ParameterError without '=' or with an empty name.
std::pair<std::string, Value> parse_assignment(std::string_view text);

}  // namespace dlfl

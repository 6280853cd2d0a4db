// The names of the enumerations (to_string): each enumerator, named in the test, has its own name, so a table
// out of step with its enumeration shows here.

#include <doctest/doctest.h>

#include <glm/vec3.hpp>
#include <initializer_list>
#include <string>
#include <vector>

#include <dlfl/attribute_types.h>
#include <dlfl/errors.h>
#include <dlfl/handles.h>
#include <dlfl/parameters.h>
#include <dlfl/validate.h>

using namespace dlfl;

namespace {

// The names of `values`, separated by spaces.
template <class E>
std::string names_of(std::initializer_list<E> values) {
  std::string s;
  for (E v : values) {
    if (!s.empty()) s += ' ';
    s += to_string(v);
  }
  return s;
}

}  // namespace

TEST_CASE("enum names: every enumerator has its own name") {
  using K = ElementKind;
  CHECK(names_of({K::vertex, K::edge, K::face, K::corner}) == "vertex edge face corner");
  using A = AttributeType;
  CHECK(names_of({A::boolean, A::integer, A::number, A::point}) == "boolean integer number point");
  using C = ViolationCode;
  CHECK(
      names_of({C::removed_reference, C::next_prev, C::corner_face, C::face_size, C::edge_corner,
                C::edge_sides, C::vertex_corner, C::pinched_vertex, C::point_sphere, C::counts,
                C::euler_characteristic}) ==
      "removed_reference next_prev corner_face face_size edge_corner edge_sides vertex_corner pinched_vertex "
      "point_sphere counts euler_characteristic");
  using T = ParamType;
  CHECK(
      names_of({T::boolean, T::integer, T::number, T::text, T::point, T::vertex, T::edge, T::face, T::corner,
                T::vertices, T::edges, T::faces, T::corners, T::numbers, T::points, T::mesh, T::params}) ==
      "boolean integer number text point vertex edge face corner vertices edges faces corners numbers points "
      "mesh params");
}

TEST_CASE("enum names: a value of the wrong kind is named in the message") {
  // Value::Kind's names appear only in messages.
  CHECK_THROWS_WITH_AS(Value(0.5).as_point(), "expected a point, got a number", InvalidArgument);
  CHECK_THROWS_WITH_AS(Value().as_bool(), "expected a boolean, got nothing", InvalidArgument);
  CHECK_THROWS_WITH_AS(Value(std::vector<glm::dvec3>{}).as_text(), "expected text, got a list of points",
                       InvalidArgument);
}

// The Meng-Prautzsch schemes at the edges of their parameters: patterns that would exhaust the stack or the
// 32-bit handles, and legal parameters so extreme that the result would not be strictly convex, are refused
// with an error that says why, before anything is produced.

#include <doctest/doctest.h>

#include <string>

#include <dlfl/errors.h>
#include <dlfl/schemes/meng_prautzsch_honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>
#include <dlfl/schemes/meng_prautzsch_pushing.h>
#include "test_meshes.h"

using namespace dlfl;

namespace {

// Runs `f`, which must throw InvalidArgument whose message contains every one of `parts`.
template <class F>
void check_refused(const F& f, std::initializer_list<const char*> parts) {
  try {
    f();
    FAIL("no exception");
  } catch (const InvalidArgument& e) {
    const std::string message = e.what();
    CAPTURE(message);
    for (const char* part : parts) CHECK(message.find(part) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("mp limits: deeply nested patterns are refused instead of exhausting the stack") {
  const std::size_t deep = mhp_max_depth;
  // At the limit a group still parses: 16 nested groups around one H expand to one step.
  CHECK(expand_mhp_pattern(std::string(deep, '(') + "H" + std::string(deep, ')')) == "H");
  // One more, or a hundred thousand more, is an error at the '(' that goes too deep (1-based: deep + 1).
  for (std::size_t depth : {deep + 1, std::size_t(100000)}) {
    CAPTURE(depth);
    check_refused([&] { expand_mhp_pattern(std::string(depth, '(') + "H" + std::string(depth, ')')); },
                  {"nested deeper than 16", ("at character " + std::to_string(deep + 1)).c_str()});
  }
}

TEST_CASE("mp limits: a pattern whose last step cannot be stored is refused before the first step") {
  // The cube has 12 edges; every H or P step multiplies them by 4. 13 steps give 12 * 4^13 = 8.05e8 edges,
  // 1.6e9 corners: fits in 32 bits (< 4.29e9). 14 steps give 6.4e9 corners: does not. (Not run: checked
  // before any step, which the instant refusal shows; 13 steps would take many gigabytes.)
  MhpParams p;
  p.pattern = "H7P7";
  check_refused([&] { mhp(test::cube(), p); }, {"mhp pattern 'H7P7'", "32-bit"});
  p.pattern = "(H8)8";
  check_refused([&] { mhp(test::cube(), p); }, {"32-bit"});
}

TEST_CASE("mp limits: extreme parameters that flatten the result are refused naming them") {
  // ratio = 1e17: the edge point's fraction ratio / (1 + ratio) rounds to exactly 1, so it lands on the
  // edge's end and a corner triangle has zero area.
  MpPushingParams p;
  p.ratio = 1e17;
  check_refused([&] { mp_pushing(test::cube(), p); }, {"mp-pushing", "ratio = 1e+17", "not strictly convex"});
  // tau = 1e-20: the vertex does not move at all in floating point, so the triangles at it stay in the
  // planes of the old faces: coplanar neighbours.
  p = {};
  p.tau = 1e-20;
  check_refused([&] { mp_pushing(test::cube(), p); }, {"mp-pushing", "tau = 1e-20", "not strictly convex"});
  // H with tau = 1e-20: the f-face does not leave its old face's plane, so the e-faces collapse.
  MpHoneycombParams h;
  h.tau = 1e-20;
  check_refused([&] { mp_honeycomb(test::cube(), h); }, {"mp-honeycomb", "tau = 1e-20"});
  // The defaults are fine, of course.
  CHECK(mp_pushing(test::cube()).num_faces() == 6 + 2 * 12);
  CHECK(mp_honeycomb(test::cube()).num_faces() == 6 + 12);
}

TEST_CASE("mp limits: epsilon is checked even with random choices off, and mhp names itself") {
  MpHoneycombParams h;
  h.random.epsilon = 0.7;  // random stays off
  check_refused([&] { check_mp_honeycomb_params(h); }, {"mp-honeycomb", "epsilon"});
  MhpParams m;
  m.honeycomb.random = {true, 0.7, 1};
  check_refused([&] { check_mhp_params(m); }, {"mhp: parameter epsilon"});
}

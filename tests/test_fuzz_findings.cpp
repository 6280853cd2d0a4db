// What fuzzing found (docs/fuzzing.md, "Findings"), as unit tests beside the regression inputs that the
// harnesses replay (tests/fuzz/regressions/).

#include <doctest/doctest.h>

#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>

using namespace dlfl;

namespace {

Mesh tetrahedron() {
  PolygonSoup soup;
  soup.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (auto f : {std::initializer_list<std::uint32_t>{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}})
    soup.add_face(f);
  return build_mesh(soup);
}

}  // namespace

TEST_CASE("fuzz findings: text parameters must be UTF-8, which is all a log's JSON can hold") {
  // `dlfl edit --op "begin_group label=$'\xcb'" --log x.json` used to throw nlohmann's type_error from
  // log_text: now the op is refused before it runs, and the log stays writable.
  for (const char* bad : {"\xcb", "a\xff", "\xc0\xaf", "\xed\xa0\x80", "\xe2\x82", "\xf4\x90\x80\x80",
                          "\xf8\x88\x80\x80\x80"}) {
    CAPTURE(std::string(bad));
    Editor editor;
    editor.set_mesh(tetrahedron());
    const std::size_t logged = editor.log().size();
    CHECK_THROWS_WITH_AS(editor.apply("begin_group", {{"label", bad}}), doctest::Contains("not valid UTF-8"),
                         ParameterError);
    CHECK(editor.log().size() == logged);
    CHECK(editor.group_depth() == 0);
    CHECK_NOTHROW(replay_log(log_text(editor)));
  }
  for (const char* good :
       {"", "plain", "caf\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80", "\xf4\x8f\xbf\xbf"}) {
    CAPTURE(std::string(good));
    Editor editor;
    editor.set_mesh(tetrahedron());
    editor.apply("begin_group", {{"label", good}});
    editor.apply("end_group");
    CHECK(replay_log(log_text(editor)).mesh() == editor.mesh());
  }
}

TEST_CASE("fuzz findings: a log whose load path is not UTF-8 is refused with a dlfl error, not a JSON one") {
  // Editor::set_mesh records its path unchecked (a file name may be any bytes); the log cannot hold it.
  Editor editor;
  editor.set_mesh(tetrahedron(), std::filesystem::path("caf\xe9.obj"));
  CHECK_THROWS_WITH_AS(log_text(editor), doctest::Contains("op 0 (load) has text that is not valid UTF-8"),
                       InvalidArgument);
}

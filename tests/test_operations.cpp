// Operations as data: the registry, parameter resolution, transactions that undo themselves, and
// operations written as text.

#include <doctest/doctest.h>

#include <cstring>
#include <set>

#include <dlfl/errors.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/operation_text.h>
#include <dlfl/operations/transaction.h>
#include <dlfl/validate.h>
#include "test_meshes.h"

using namespace dlfl;

namespace {

// The error a call throws, as its type, to look at the parameter it names.
template <class E, class F>
E error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e;
  }
  FAIL("no error of the expected type");
  return E("", "");
}

}  // namespace

TEST_CASE("operations: the registry holds every operation once, sorted, each parameter documented") {
  std::set<std::string> seen;
  std::string previous;
  for (const OperationSpec& op : operations()) {
    CAPTURE(op.name);
    CHECK(seen.insert(op.name).second);
    CHECK(op.name > previous);
    previous = op.name;
    CHECK_FALSE(op.doc.empty());
    switch (op.kind) {
      case OperationSpec::Kind::edit:
        CHECK(op.edit);
        break;
      case OperationSpec::Kind::replace:
        CHECK(op.replace);
        break;
      case OperationSpec::Kind::history:
        CHECK_FALSE(op.edit);
        break;
    }
    for (const ParamSpec& p : op.params) {
      CAPTURE(p.name);
      CHECK_FALSE(p.doc.empty());
    }
  }
  // Today's operators and the log's whole-mesh and history ops are all entries.
  for (const char* name : {"create_vertex", "delete_vertex", "insert_edge", "delete_edge", "subdivide_edge",
                           "unsubdivide_edge", "set_position", "create_face_manifold", "load", "mesh",
                           "subdivide", "undo", "redo", "begin_group", "end_group", "clear_history"}) {
    CAPTURE(name);
    CHECK(find_operation(name).name == name);
  }
}

TEST_CASE("operations: a misspelled name gets a suggestion, a far one none") {
  const auto near = error_of<UnknownNameError>([] { find_operation("insert_egde"); });
  CHECK(near.suggestion() == "insert_edge");
  CHECK(std::string(near.what()).find("did you mean 'insert_edge'?") != std::string::npos);
  const auto far = error_of<UnknownNameError>([] { find_operation("frobnicate"); });
  CHECK(far.suggestion().empty());
  CHECK(std::string(far.what()).find("known: ") != std::string::npos);
}

TEST_CASE("operations: parameters are checked by their declarations before anything changes") {
  Mesh m = build_mesh(test::cube_soup());
  const Mesh before = m;
  const auto unknown = error_of<ParameterError>([&] {
    apply_operation(m, "insert_edge", {{"corner1", 0}, {"corner3", 2}});
  });
  CHECK(unknown.parameter() == "corner3");
  CHECK(std::string(unknown.what()).find("did you mean 'corner1'") != std::string::npos);
  const auto missing = error_of<ParameterError>([&] { apply_operation(m, "insert_edge", {{"corner1", 0}}); });
  CHECK(missing.parameter() == "corner2");
  const auto wrong_type = error_of<ParameterError>([&] {
    apply_operation(m, "set_position", {{"vertex", 0}, {"position", "1,2"}});
  });
  CHECK(wrong_type.parameter() == "position");
  const auto dead = error_of<ParameterError>([&] {
    apply_operation(m, "insert_edge", {{"corner1", 0}, {"corner2", CornerId(m.corner_capacity())}});
  });
  CHECK(dead.parameter() == "corner2");
  const auto negative = error_of<ParameterError>([&] { apply_operation(m, "delete_edge", {{"edge", -1}}); });
  CHECK(negative.parameter() == "edge");
  const auto not_finite = error_of<ParameterError>([&] {
    apply_operation(m, "set_position", {{"vertex", 0}, {"position", glm::dvec3(0, std::nan(""), 0)}});
  });
  CHECK(not_finite.parameter() == "position");
  const auto range = error_of<ParameterError>([&] {
    apply_operation(m, "subdivide", {{"scheme", "honeycomb"}, {"iterations", 65}});
  });
  CHECK(range.parameter() == "iterations");
  CHECK(std::string(range.what()).find("= 65 is outside [0, 64]") != std::string::npos);
  CHECK(m == before);
  CHECK(mesh_hash(m) == mesh_hash(before));
}

TEST_CASE("operations: text values are read by their declared type") {
  Mesh m = build_mesh(test::cube_soup());
  // "x,y,z" for a point, a number for a handle; the default position of subdivide_edge is the midpoint.
  apply_operation(m, "set_position", {{"vertex", "3"}, {"position", "0.25,-1e-3,2"}});
  CHECK(m.position(VertexId(3)) == glm::dvec3(0.25, -1e-3, 2));
  const EdgeId e(0);
  const glm::dvec3 mid = 0.5 * (m.position(m.from(e)) + m.position(m.to(e)));
  const Params out = apply_operation(m, "subdivide_edge", {{"edge", "0"}});
  CHECK(m.position(out.handle<VertexId>("vertex")) == mid);
  // A list of points "x,y,z;x,y,z".
  const std::size_t faces = m.num_faces();
  apply_operation(m, "create_face_manifold", {{"positions", "0,0,5;1,0,5;0,1,5"}});
  CHECK(m.num_faces() == faces + 2);
  CHECK(validate(m).valid());
}

TEST_CASE("operations: an integer literal works where a number is expected") {
  Mesh a = build_mesh(test::cube_soup());
  Mesh b = a;
  apply_operation(a, "subdivide", {{"scheme", "honeycomb"}, {"params", Params{{"t", 1}}}});
  apply_operation(b, "subdivide", {{"scheme", "honeycomb"}, {"params", Params{{"t", 1.0}}}});
  CHECK(a == b);
  // And differs from the default t = 0.5, so the value was used.
  Mesh c = build_mesh(test::cube_soup());
  apply_operation(c, "subdivide", {{"scheme", "honeycomb"}});
  CHECK_FALSE(a == c);
}

TEST_CASE("transactions: a composite operation that fails part-way leaves the mesh exactly as it was") {
  Mesh m = build_mesh(test::torus_soup(4, 3));
  const Mesh before = m;
  const std::string hash = mesh_hash(m);
  CHECK_THROWS_AS(
      [&] {
        Transaction tx(m);
        const FaceId f = *m.faces().begin();
        const CornerId c = m.first_corner(f);
        tx.insert_edge(c, m.next(m.next(c)));  // splits f
        const VertexId v = tx.subdivide_edge(EdgeId(0), glm::dvec3(9, 9, 9));
        tx.set_position(v, glm::dvec3(1, 2, 3));
        tx.create_face_manifold(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        CHECK(tx.size() == 3 + 6);  // the face manifold records its 3 vertices and 3 edges
        tx.insert_edge(c, c);       // a self-loop: TopologyError, and the destructor reverts the rest
      }(),
      TopologyError);
  CHECK(m == before);
  CHECK(mesh_hash(m) == hash);
}

TEST_CASE("transactions: the committed record undoes and redoes exactly") {
  Mesh m = build_mesh(test::cube_soup());
  const Mesh start = m;
  ChangeRecord record;
  {
    Transaction tx(m);
    const CornerId c = m.first_corner(FaceId(0));
    const InsertEdgeResult r = tx.insert_edge(c, m.next(m.next(c)));
    const VertexId v = tx.subdivide_edge(r.edge, glm::dvec3(0.1, 0.2, 0.3));
    const VertexId p = tx.create_vertex(glm::dvec3(5, 5, 5));
    tx.insert_edge(m.corner(p), m.corner(v));
    record = tx.commit();
  }
  const Mesh end = m;
  CHECK(record.size() == 4);
  record.revert(m);
  CHECK(m == start);
  record.revert(m);
  CHECK(m == end);
  CHECK(mesh_hash(m) == mesh_hash(end));
  CHECK(validate(m).valid());
}

namespace {

// Every field of two steps alike, positions bit for bit.
bool same_step(const Step& x, const Step& y) {
  const detail::Reuse &r = x.reuse, &q = y.reuse;
  bool same = x.kind == y.kind && x.hole == y.hole && x.vertex == y.vertex && x.edge == y.edge &&
              x.face == y.face && x.corner1 == y.corner1 && x.corner2 == y.corner2 &&
              std::memcmp(&x.position, &y.position, sizeof(x.position)) == 0 && r.edge == q.edge &&
              r.face == q.face && r.vertex == q.vertex;
  for (int i = 0; i < 2; ++i) {
    same = same && r.corners[i] == q.corners[i] && r.face_anchors[i].face == q.face_anchors[i].face &&
           r.face_anchors[i].corner == q.face_anchors[i].corner &&
           r.vertex_anchors[i].vertex == q.vertex_anchors[i].vertex &&
           r.vertex_anchors[i].corner == q.vertex_anchors[i].corner;
  }
  return same;
}

}  // namespace

TEST_CASE("transactions: the record gives back each inverse exactly as the operator returned it") {
  // The same steps on a twin through Mesh::apply give the inverses to expect (the record keeps the common
  // ones packed, so this checks that nothing is lost in the packing).
  Mesh m = build_mesh(test::torus_soup(4, 3));
  Mesh twin = m;
  std::vector<Step> expected;
  Transaction tx(m);
  auto run = [&](const Step& step) {
    tx.apply(step);
    expected.push_back(twin.apply(step));
  };
  for (int k = 0; k < 6; ++k) {  // splits of faces of several sizes, from several corners
    const CornerId c = m.first_corner(FaceId(std::uint32_t(2 * k)));
    run(Step{.kind = Step::Kind::insert_edge, .corner1 = m.next(c), .corner2 = m.prev(c)});
  }
  run(Step{.kind = Step::Kind::create_vertex, .position = glm::dvec3(-0.0, 1.5, 2)});
  const VertexId sphere(m.vertex_capacity() - 1);
  run(Step{
      .kind = Step::Kind::insert_edge, .corner1 = m.first_corner(FaceId(1)), .corner2 = m.corner(sphere)});
  run(Step{.kind = Step::Kind::delete_edge, .edge = EdgeId(3)});
  run(Step{.kind = Step::Kind::set_position, .vertex = VertexId(2), .position = glm::dvec3(7, 8, 9)});
  run(Step{.kind = Step::Kind::set_hole, .hole = true, .face = FaceId(5)});
  tx.add_attribute(ElementKind::vertex, "w", AttributeValue(1.0));
  tx.set_attribute(ElementKind::vertex, "w", 4, AttributeValue(2.5));
  const ChangeRecord record = tx.commit();
  CHECK(m.num_faces() == twin.num_faces());
  REQUIRE(record.size() == expected.size() + 2);
  bool anchored = false, merged = false;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    CAPTURE(i);
    CHECK(same_step(std::get<Step>(record.inverse(i)), expected[i]));
    anchored = anchored || expected[i].reuse.face_anchors[0].face.valid();
    merged = merged || (expected[i].kind == Step::Kind::delete_edge && expected[i].reuse.face.valid());
  }
  CHECK(anchored);  // a split that moved its face's first corner was among them
  CHECK(merged);
  CHECK(std::get<AttributeCreation>(record.inverse(expected.size())).present == false);
  const AttributeWrite write = std::get<AttributeWrite>(record.inverse(expected.size() + 1));
  CHECK(write.index == 4);
  CHECK(std::get<double>(write.value) == 1.0);
}

TEST_CASE("transactions: appended records revert as one, and twice redo") {
  Mesh m = build_mesh(test::cube_soup());
  const Mesh start = m;
  ChangeRecord record;
  for (int k = 0; k < 3; ++k) {
    Transaction tx(m);
    const CornerId c = m.first_corner(FaceId(std::uint32_t(k)));
    tx.insert_edge(c, m.next(m.next(c)));
    tx.set_position(VertexId(std::uint32_t(k)), glm::dvec3(k, -k, 0.5));
    const VertexId p = tx.create_vertex(glm::dvec3(5, 5, k));
    tx.insert_edge(m.corner(p), c);
    record.append(tx.commit());
  }
  const Mesh end = m;
  CHECK(record.size() == 12);
  record.revert(m);
  CHECK(m == start);
  record.revert(m);
  CHECK(m == end);
  record.revert(m);
  CHECK(m == start);
}

TEST_CASE("operations: text is split into a name and parameters") {
  auto [name, params] = parse_operation_text("  insert_edge corner1=0   corner2='2' ");
  CHECK(name == "insert_edge");
  CHECK(params.size() == 2);
  CHECK(params.text("corner1") == "0");
  CHECK(params.text("corner2") == "2");
  auto [sub, nested] = parse_operation_text("subdivide scheme=honeycomb params.t=0.4 params.a=\"0.5\"");
  CHECK(sub == "subdivide");
  CHECK(nested.get("params").as_params().text("t") == "0.4");
  CHECK(nested.get("params").as_params().text("a") == "0.5");
  CHECK(parse_operation_text("begin_group label='two words'").second.text("label") == "two words");
  CHECK_THROWS_AS(parse_operation_text("insert_edge corner1=0 corner1=1"), ParameterError);
  CHECK_THROWS_AS(parse_operation_text("insert_edge corner1"), ParameterError);
  CHECK_THROWS_AS(parse_operation_text("insert_edge =1"), ParameterError);
  CHECK_THROWS_AS(parse_operation_text("   "), InvalidArgument);
  CHECK_THROWS_AS(parse_operation_text("begin_group label='open"), InvalidArgument);
  CHECK_THROWS_AS(parse_operation_text("subdivide params.=1"), ParameterError);
}

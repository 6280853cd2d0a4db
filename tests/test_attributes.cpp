// Named mesh attributes: the typed and the type-erased API, their life through operators, inverse steps and
// compact(), equality and hashing, MeshArrays and the native JSON format.

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/io/json_mesh.h>
#include <dlfl/mesh_arrays.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include <dlfl/validate.h>
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

// A cube with tombstones between live elements of every kind: a removed point sphere (vertex, face, corner)
// before a kept one, a removed diagonal (edge, corners, face), and a removed cube edge (edge, two corners of
// low index, one of the original faces).
struct CubeWithTombstones {
  Mesh mesh = test::cube();
  VertexId removed_vertex;
  FaceId removed_face;
  EdgeId removed_edge;
  CubeWithTombstones() {
    removed_vertex = mesh.create_vertex({4, 4, 4});
    mesh.create_vertex({5, 5, 5});
    mesh.delete_vertex(removed_vertex);
    const CornerId c = mesh.first_corner(FaceId(0));
    const InsertEdgeResult split = mesh.insert_edge(c, mesh.next(mesh.next(c)));
    removed_face = split.created_face;
    removed_edge = split.edge;
    mesh.delete_edge(removed_edge);
    mesh.delete_edge(EdgeId(0));
  }
};

}  // namespace

TEST_CASE("attributes: typed access, lookup, errors") {
  Mesh m = test::cube();
  CHECK_FALSE(m.has_vertex_attribute("weight"));
  VertexAttribute<double> weight = m.add_vertex_attribute<double>("weight", 0.5);
  CHECK(m.has_vertex_attribute("weight"));
  CHECK_FALSE(m.has_face_attribute("weight"));  // names are per element kind
  for (VertexId v : m.vertices()) CHECK(weight[v] == 0.5);
  weight[VertexId(3)] = 2.0;
  CHECK(m.vertex_attribute<double>("weight")[VertexId(3)] == 2.0);
  const Mesh& read_only = m;
  const ConstAttribute<VertexId, double> seen = read_only.vertex_attribute<double>("weight");
  CHECK(seen[VertexId(3)] == 2.0);
  CHECK(seen[VertexId(4)] == 0.5);
  CHECK(seen.default_value() == 0.5);
  // Adding it again with the same type gives the same attribute, values and default unchanged.
  VertexAttribute<double> again = m.add_vertex_attribute<double>("weight", 9.0);
  CHECK(again[VertexId(3)] == 2.0);
  CHECK(again.default_value() == 0.5);
  // The other kinds, through their wrappers and the generic template.
  m.add_edge_attribute<int>("crease", 0)[EdgeId(1)] = 3;
  m.add_face_attribute<glm::dvec3>("colour", glm::dvec3(1, 0, 0));
  m.add_corner_attribute<bool>("seam")[CornerId(5)] = true;
  CHECK(m.attribute<EdgeId, int>("crease")[EdgeId(1)] == 3);
  CHECK(m.has_attribute<FaceId>("colour"));
  CHECK(m.corner_attribute<bool>("seam")[CornerId(5)]);
  CHECK_FALSE(m.corner_attribute<bool>("seam")[CornerId(6)]);
  CHECK(m.find_attribute<FaceId, glm::dvec3>("colour").has_value());
  CHECK_FALSE(m.find_attribute<FaceId, glm::dvec3>("missing").has_value());

  // Errors name the attribute and the types.
  const std::string wrong_type =
      test::error_message<InvalidArgument>([&] { m.vertex_attribute<int>("weight"); });
  CHECK(wrong_type.find("'weight'") != std::string::npos);
  CHECK(wrong_type.find("number") != std::string::npos);
  CHECK(wrong_type.find("integer") != std::string::npos);
  const std::string missing =
      test::error_message<InvalidArgument>([&] { m.face_attribute<double>("weight"); });
  CHECK(missing.find("face attribute 'weight'") != std::string::npos);
  CHECK(missing.find("number") != std::string::npos);
  CHECK_THROWS_AS(m.add_vertex_attribute<int>("weight"), InvalidArgument);
  CHECK_THROWS_AS((m.find_attribute<FaceId, int>("colour")), InvalidArgument);
  CHECK_THROWS_AS(m.add_vertex_attribute<int>(""), InvalidArgument);
  CHECK_THROWS_AS(m.remove_edge_attribute("weight"), InvalidArgument);
  m.remove_vertex_attribute("weight");
  CHECK_FALSE(m.has_vertex_attribute("weight"));
  CHECK_THROWS_AS(m.vertex_attribute<double>("weight"), InvalidArgument);
}

TEST_CASE("attributes: the type-erased API") {
  Mesh m = test::cube();
  m.add_attribute(ElementKind::corner, "c", AttributeValue(false));
  m.add_attribute(ElementKind::face, "b", AttributeValue(glm::dvec3(1, 2, 3)));
  m.add_attribute(ElementKind::vertex, "z", AttributeValue(1));
  m.add_attribute(ElementKind::vertex, "a", AttributeValue(0.25));
  const std::vector<AttributeInfo> list = m.attributes();
  REQUIRE(list.size() == 4);
  // Sorted by kind (vertex, edge, face, corner), then by name.
  CHECK(list[0].name == "a");
  CHECK(list[0].type == AttributeType::number);
  CHECK(std::get<double>(list[0].default_value) == 0.25);
  CHECK(list[1].name == "z");
  CHECK(list[1].type == AttributeType::integer);
  CHECK(list[2].name == "b");
  CHECK(list[2].kind == ElementKind::face);
  CHECK(list[2].type == AttributeType::point);
  CHECK(list[3].name == "c");
  CHECK(list[3].kind == ElementKind::corner);
  CHECK(list[3].type == AttributeType::boolean);

  CHECK(m.has_attribute(ElementKind::vertex, "z"));
  CHECK_FALSE(m.has_attribute(ElementKind::edge, "z"));
  m.add_attribute(ElementKind::vertex, "z", AttributeValue(5));  // same type: nothing changes
  CHECK(std::get<int>(m.attribute_value(ElementKind::vertex, "z", 0)) == 1);
  CHECK_THROWS_AS(m.add_attribute(ElementKind::vertex, "z", AttributeValue(5.0)), InvalidArgument);

  m.set_attribute_value(ElementKind::vertex, "z", 7, AttributeValue(-4));
  CHECK(m.vertex_attribute<int>("z")[VertexId(7)] == -4);  // the typed view sees it
  CHECK(std::get<int>(m.attribute_value(ElementKind::vertex, "z", 7)) == -4);
  CHECK(std::get<glm::dvec3>(m.attribute_value(ElementKind::face, "b", 5)) == glm::dvec3(1, 2, 3));
  // Bad input: wrong type, index past the capacity, missing attribute; the value stays.
  CHECK_THROWS_AS(m.set_attribute_value(ElementKind::vertex, "z", 7, AttributeValue(true)), InvalidArgument);
  CHECK_THROWS_AS(m.set_attribute_value(ElementKind::vertex, "z", 8, AttributeValue(1)), InvalidArgument);
  CHECK_THROWS_AS(m.attribute_value(ElementKind::face, "b", 6), InvalidArgument);
  CHECK_THROWS_AS(m.attribute_value(ElementKind::edge, "b", 0), InvalidArgument);
  CHECK(std::get<int>(m.attribute_value(ElementKind::vertex, "z", 7)) == -4);
  m.remove_attribute(ElementKind::face, "b");
  CHECK(m.attributes().size() == 3);
  CHECK_THROWS_AS(m.remove_attribute(ElementKind::face, "b"), InvalidArgument);
}

TEST_CASE("attributes: new elements read the default, removed ones keep their value for an undo") {
  Mesh m = test::cube();
  auto weight = m.add_vertex_attribute<double>("weight", -1.0);
  auto label = m.add_edge_attribute<int>("label", 0);
  for (EdgeId e : m.edges()) label[e] = int(e.index()) + 100;
  const EdgeId e(4);
  const Step inverse = [&] {
    Step s{Step::Kind::subdivide_edge};
    s.edge = e;
    s.position = glm::dvec3(0.5);
    return m.apply(s);
  }();
  const VertexId middle = inverse.vertex;
  CHECK(weight[middle] == -1.0);  // new vertex: the default
  CHECK(label[EdgeId(12)] == 0);  // the new edge too
  CHECK(label[e] == 104);         // the split edge keeps its value
  weight[middle] = 8.0;
  const Step redo = m.apply(inverse);  // removes the vertex and the new edge
  CHECK_FALSE(m.is_alive(middle));
  CHECK(weight.get(middle) == 8.0);  // the slot stays
  m.apply(redo);                     // brings the same vertex back ...
  REQUIRE(m.is_alive(middle));
  CHECK(weight[middle] == 8.0);  // ... with its value
}

TEST_CASE("attributes: survive random operators and their exact undo, removed values coming back") {
  Mesh m = build_mesh(test::torus_soup(5, 4));
  std::mt19937_64 rng(20240601);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto below = [&](std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng); };
  auto weight = m.add_vertex_attribute<double>("weight", 0.0);
  auto label = m.add_edge_attribute<int>("label", -1);
  auto colour = m.add_face_attribute<glm::dvec3>("colour", glm::dvec3(not_a_number));
  auto seam = m.add_corner_attribute<bool>("seam", false);
  auto fill_new = [&](std::uint32_t v0, std::uint32_t e0, std::uint32_t f0, std::uint32_t c0) {
    for (std::uint32_t i = v0; i < m.vertex_capacity(); ++i) weight[VertexId(i)] = uniform(1, 2);
    for (std::uint32_t i = e0; i < m.edge_capacity(); ++i) label[EdgeId(i)] = int(below(1000));
    for (std::uint32_t i = f0; i < m.face_capacity(); ++i) colour[FaceId(i)] = glm::dvec3(uniform(0, 1));
    for (std::uint32_t i = c0; i < m.corner_capacity(); ++i) seam[CornerId(i)] = below(2) == 1;
  };
  fill_new(0, 0, 0, 0);

  // Random steps; a step the mesh refuses changes nothing (that is the contract) and is skipped. After each
  // step only the elements it appended get values, so undoing back to a checkpoint must give the checkpoint.
  std::vector<Step> inverses;
  std::vector<std::pair<std::size_t, Mesh>> checkpoints{{0, m}};
  std::size_t removed_with_value = 0;
  while (inverses.size() < 20000) {
    Step s;
    switch (below(8)) {
      case 0:
        s.kind = Step::Kind::create_vertex;
        s.position = glm::dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        break;
      case 1:
        s.kind = Step::Kind::delete_vertex;
        s.vertex = VertexId(below(m.vertex_capacity()));
        break;
      case 2:
      case 3: {
        s.kind = Step::Kind::insert_edge;
        s.corner1 = CornerId(below(m.corner_capacity()));
        s.corner2 = CornerId(below(m.corner_capacity()));
        if (m.is_alive(s.corner1) && below(2) == 0) s.corner2 = m.next(m.next(s.corner1));  // often a split
        break;
      }
      case 4:
      case 5:
        s.kind = Step::Kind::delete_edge;
        s.edge = EdgeId(below(m.edge_capacity()));
        break;
      case 6:
        s.kind = below(2) ? Step::Kind::subdivide_edge : Step::Kind::unsubdivide_edge;
        s.edge = EdgeId(below(m.edge_capacity()));
        s.vertex = VertexId(below(m.vertex_capacity()));
        s.position = glm::dvec3(uniform(-1, 1));
        break;
      default:
        s.kind = Step::Kind::set_hole;
        s.face = FaceId(below(m.face_capacity()));
        s.hole = below(2) == 1;
        break;
    }
    if (m.num_edges() > 300 && (s.kind == Step::Kind::insert_edge || s.kind == Step::Kind::subdivide_edge))
      continue;  // keep the mesh small
    const std::uint32_t v0 = m.vertex_capacity(), e0 = m.edge_capacity(), f0 = m.face_capacity(),
                        c0 = m.corner_capacity();
    const std::size_t live_before = m.num_vertices() + m.num_edges() + m.num_faces();
    try {
      inverses.push_back(m.apply(s));
    } catch (const Error&) {
      continue;
    }
    removed_with_value += m.num_vertices() + m.num_edges() + m.num_faces() < live_before;
    fill_new(v0, e0, f0, c0);
    if (inverses.size() % 500 == 0) checkpoints.emplace_back(inverses.size(), m);
  }
  require_valid(m);
  CHECK(removed_with_value > 3000);  // many steps removed elements that carried values

  const Mesh end = m;
  if (checkpoints.back().first == inverses.size()) checkpoints.pop_back();  // the end itself
  while (!inverses.empty()) {
    m.apply(inverses.back());
    inverses.pop_back();
    if (checkpoints.back().first == inverses.size()) {
      CAPTURE(inverses.size());
      REQUIRE(m == checkpoints.back().second);
      CHECK(mesh_hash(m) == mesh_hash(checkpoints.back().second));
      checkpoints.pop_back();
    }
  }
  CHECK(checkpoints.empty());
  CHECK_FALSE(m == end);
}

TEST_CASE("attributes: compact moves the values with their elements") {
  CubeWithTombstones t;
  Mesh& m = t.mesh;
  auto where = m.add_vertex_attribute<glm::dvec3>("where");
  auto centre = m.add_face_attribute<glm::dvec3>("centre");
  auto ends = m.add_edge_attribute<double>("length");
  auto valence = m.add_corner_attribute<int>("valence");
  for (VertexId v : m.vertices()) where[v] = m.position(v);
  for (FaceId f : m.faces()) centre[f] = face_centroid(m, f);
  for (EdgeId e : m.edges()) ends[e] = glm::length(m.position(m.from(e)) - m.position(m.to(e)));
  for (CornerId c : m.corners()) valence[c] = int(m.valence(m.vertex(c)));
  const Mesh before = m;
  m.compact();
  REQUIRE(m.vertex_capacity() < before.vertex_capacity());
  REQUIRE(m.face_capacity() < before.face_capacity());
  for (VertexId v : m.vertices()) CHECK(where[v] == m.position(v));
  for (FaceId f : m.faces()) CHECK(centre[f] == face_centroid(m, f));
  for (EdgeId e : m.edges()) CHECK(ends[e] == glm::length(m.position(m.from(e)) - m.position(m.to(e))));
  for (CornerId c : m.corners()) CHECK(valence[c] == int(m.valence(m.vertex(c))));
  // Handles survive the compaction (the storage is the mesh's, moved in place).
  CHECK(m.vertex_attribute<glm::dvec3>("where")[VertexId(0)] == m.position(VertexId(0)));
}

TEST_CASE("attributes: copies are deep, moves keep the handles working") {
  Mesh a = test::cube();
  auto w = a.add_vertex_attribute<int>("w", 0);
  w[VertexId(1)] = 10;
  Mesh b = a;
  b.vertex_attribute<int>("w")[VertexId(1)] = 20;
  CHECK(w[VertexId(1)] == 10);  // the copy has its own values
  CHECK_FALSE(a == b);
  Mesh c = std::move(a);
  w[VertexId(2)] = 30;  // the handle now reads and writes c's attribute
  CHECK(c.vertex_attribute<int>("w")[VertexId(2)] == 30);
  CHECK(c.vertex_attribute<int>("w")[VertexId(1)] == 10);
}

TEST_CASE("attributes: operator== and mesh_hash see every difference on live elements") {
  CubeWithTombstones ta, tb;
  Mesh& a = ta.mesh;
  Mesh& b = tb.mesh;
  REQUIRE(a == b);
  const std::string plain = mesh_hash(a);
  auto same = [&] { return a == b && mesh_hash(a) == mesh_hash(b); };
  auto differ = [&] { return !(a == b) && mesh_hash(a) != mesh_hash(b); };

  a.add_vertex_attribute<double>("w", 1.0);
  CHECK(differ());  // one mesh has an attribute the other has not
  b.add_vertex_attribute<double>("w", 2.0);
  CHECK(differ());  // different defaults
  b.remove_vertex_attribute("w");
  b.add_vertex_attribute<int>("w", 1);
  CHECK(differ());  // different types
  b.remove_vertex_attribute("w");
  b.add_face_attribute<double>("w", 1.0);
  CHECK(differ());  // different kinds
  b.remove_face_attribute("w");
  b.add_vertex_attribute<double>("w", 1.0);
  CHECK(same());

  a.vertex_attribute<double>("w")[VertexId(5)] = 3.0;
  CHECK(differ());  // a value on a live element
  b.vertex_attribute<double>("w")[VertexId(5)] = 3.0;
  CHECK(same());
  // A value written in one mesh only, equal to the default, is no difference.
  a.vertex_attribute<double>("w")[VertexId(6)] = 1.0;
  CHECK(same());
  // Nor one on a removed element.
  a.vertex_attribute<double>("w")[ta.removed_vertex] = 99.0;
  CHECK(same());
  // 0.0 and -0.0 differ (bit for bit); any NaN equals any NaN.
  a.vertex_attribute<double>("w")[VertexId(0)] = 0.0;
  b.vertex_attribute<double>("w")[VertexId(0)] = -0.0;
  CHECK(differ());
  b.vertex_attribute<double>("w")[VertexId(0)] = 0.0;
  a.vertex_attribute<double>("w")[VertexId(1)] = std::nan("1");
  b.vertex_attribute<double>("w")[VertexId(1)] = -std::nan("2");
  REQUIRE(std::bit_cast<std::uint64_t>(a.vertex_attribute<double>("w")[VertexId(1)]) !=
          std::bit_cast<std::uint64_t>(b.vertex_attribute<double>("w")[VertexId(1)]));
  CHECK(same());
  // The other types, on the other kinds.
  const CornerId corner = *a.corners().begin();
  a.add_corner_attribute<bool>("seam")[corner] = true;
  b.add_corner_attribute<bool>("seam");
  CHECK(differ());
  b.corner_attribute<bool>("seam")[corner] = true;
  CHECK(same());
  a.add_edge_attribute<glm::dvec3>("dir")[EdgeId(2)] = glm::dvec3(0, 0, 1);
  b.add_edge_attribute<glm::dvec3>("dir")[EdgeId(2)] = glm::dvec3(0, 1, 0);
  CHECK(differ());
  // Removing everything gives back the digest of the bare mesh.
  for (Mesh* m : {&a, &b}) {
    for (const AttributeInfo& info : m->attributes()) m->remove_attribute(info.kind, info.name);
  }
  CHECK(same());
  CHECK(mesh_hash(a) == plain);
}

TEST_CASE("attributes: digests of meshes without attributes and of face points are those of the old kernel") {
  // Computed by the kernel before attributes existed (commit 69463ee), where the control point was a field.
  CHECK(mesh_hash(test::cube()) == "093b361f11514b51b865f16332ce92c0");
  Mesh m = test::cube();
  set_face_point(m, FaceId(2), glm::dvec3(0.25, -0.5, 2.0));
  set_face_point(m, FaceId(4), glm::dvec3(1.0 / 3.0, 0, -1));
  set_face_point(m, FaceId(4), std::nullopt);
  set_face_point(m, FaceId(5), glm::dvec3(-0.0, 1e-300, 3));
  CHECK(mesh_hash(m) == "68c84dc8aca850effa6124fc201c38cd");
  CHECK(mesh_hash(zhang_wang_honeycomb(test::tetrahedron())) == "bd21c7f252b5c4a20fe51af631fdb857");
}

TEST_CASE("attributes: MeshArrays keeps every slot, removed ones included") {
  CubeWithTombstones t;
  Mesh& m = t.mesh;
  m.add_vertex_attribute<int>("id", -1)[t.removed_vertex] = 77;
  m.add_face_attribute<bool>("picked")[t.removed_face] = true;
  m.vertex_attribute<int>("id")[VertexId(2)] = 2;
  REQUIRE_FALSE(m.is_alive(t.removed_vertex));
  REQUIRE_FALSE(m.is_alive(t.removed_face));
  const MeshArrays arrays = MeshArrays::from(m);
  REQUIRE(arrays.attributes.size() == 2);
  CHECK(arrays.attributes[0].name == "id");
  CHECK(arrays.attributes[0].values.size() == m.vertex_capacity());
  CHECK(std::get<int>(arrays.attributes[0].values[t.removed_vertex.index()]) == 77);
  const Mesh back = arrays.to_mesh();
  CHECK(back == m);
  CHECK(std::get<int>(back.attribute_value(ElementKind::vertex, "id", t.removed_vertex.index())) == 77);
  CHECK(std::get<bool>(back.attribute_value(ElementKind::face, "picked", t.removed_face.index())));

  MeshArrays bad = arrays;
  bad.attributes[0].values.pop_back();
  CHECK_THROWS_AS(bad.to_mesh(), TopologyError);
  bad = arrays;
  bad.attributes[0].values[0] = 1.5;
  CHECK_THROWS_WITH_AS(bad.to_mesh(), doctest::Contains("value 0 is not of type integer"), TopologyError);
  bad = arrays;
  bad.attributes.push_back(arrays.attributes[0]);
  CHECK_THROWS_WITH_AS(bad.to_mesh(), doctest::Contains("given twice"), TopologyError);
}

TEST_CASE("attributes: native JSON round trip with NaN, infinities and removed slots") {
  CubeWithTombstones t;
  Mesh& m = t.mesh;
  auto weight = m.add_vertex_attribute<double>("weight", not_a_number);
  auto tip = m.add_face_attribute<glm::dvec3>("tip", glm::dvec3(0.0));
  auto count = m.add_edge_attribute<int>("count", 0);
  auto seam = m.add_corner_attribute<bool>("seam", false);
  weight[VertexId(0)] = 1.25;
  weight[VertexId(1)] = inf;
  weight[VertexId(2)] = -inf;
  weight[VertexId(3)] = -0.0;
  weight[t.removed_vertex] = 5.0;  // a removed slot: not saved
  const FaceId face = *m.faces().begin();
  const EdgeId edge = *m.edges().begin();
  const CornerId corner = *m.corners().begin();
  tip[face] = glm::dvec3(not_a_number, 2.5, -inf);
  tip[t.removed_face] = glm::dvec3(9.0);
  count[edge] = std::numeric_limits<int>::min();
  count[EdgeId(edge.index() + 1)] = std::numeric_limits<int>::max();
  seam[corner] = true;

  const nlohmann::json doc = mesh_to_json(m);
  REQUIRE(doc["attributes"].size() == 4);
  // In (kind, name) order; a NaN is null, an infinity a string, a removed slot null.
  const nlohmann::json& w = doc["attributes"][0];
  CHECK(w["name"] == "weight");
  CHECK(w["element"] == "vertex");
  CHECK(w["type"] == "number");
  CHECK(w["default"].is_null());
  CHECK(w["values"].size() == m.vertex_capacity());
  CHECK(w["values"][0] == 1.25);
  CHECK(w["values"][1] == "inf");
  CHECK(w["values"][2] == "-inf");
  CHECK(w["values"][4].is_null());  // NaN, the default
  CHECK(w["values"][8].is_null());  // the removed vertex
  CHECK(w["values"][t.removed_vertex.index()].is_null());
  CHECK(doc["attributes"][1]["name"] == "count");
  const nlohmann::json& p = doc["attributes"][2];
  CHECK(p["name"] == "tip");
  CHECK(p["values"][face.index()] == nlohmann::json({nullptr, 2.5, "-inf"}));
  CHECK(p["values"][t.removed_face.index()].is_null());
  CHECK(doc["attributes"][1]["values"][edge.index()] == std::numeric_limits<int>::min());
  CHECK(doc["attributes"][3]["values"][corner.index()] == true);

  const Mesh back = mesh_from_json(nlohmann::json::parse(doc.dump()), "round trip");
  CHECK(back == m);
  CHECK(mesh_hash(back) == mesh_hash(m));
  CHECK(std::isnan(back.vertex_attribute<double>("weight")[VertexId(5)]));
  CHECK(std::signbit(back.vertex_attribute<double>("weight")[VertexId(3)]));
  // Removed slots come back with the default.
  CHECK(std::isnan(back.vertex_attribute<double>("weight")[t.removed_vertex]));
  CHECK(back.face_attribute<glm::dvec3>("tip")[t.removed_face] == glm::dvec3(0.0));
  // And a mesh without attributes writes no "attributes" at all.
  CHECK_FALSE(mesh_to_json(test::cube()).contains("attributes"));
}

TEST_CASE("attributes: malformed JSON attributes are refused naming the field") {
  Mesh m = test::cube();
  m.add_vertex_attribute<int>("id", 0);
  const nlohmann::json good = mesh_to_json(m);
  auto refused = [&](auto&& edit, const std::string& field) {
    nlohmann::json doc = good;
    edit(doc["attributes"][0]);
    CAPTURE(field);
    CHECK_THROWS_WITH_AS(mesh_from_json(doc, "bad.json"), doctest::Contains(field.c_str()), IoError);
  };
  refused([](nlohmann::json& a) { a["values"][2] = 1.5; }, "attributes[0].values[2]");
  refused([](nlohmann::json& a) { a["values"][2] = 5000000000ll; }, "attributes[0].values[2]");
  refused([](nlohmann::json& a) { a["values"].erase(0); }, "attributes[0].values");
  refused([](nlohmann::json& a) { a["element"] = "cell"; }, "attributes[0].element");
  refused([](nlohmann::json& a) { a["type"] = "string"; }, "attributes[0].type");
  refused([](nlohmann::json& a) { a["name"] = ""; }, "attributes[0].name");
  refused([](nlohmann::json& a) { a.erase("default"); }, "attributes[0].default");
  refused([](nlohmann::json& a) { a["type"] = "point"; }, "attributes[0].default");
  // A removed slot must be null.
  Mesh with_hole = test::cube();
  with_hole.delete_vertex(with_hole.create_vertex({3, 3, 3}));
  with_hole.add_vertex_attribute<int>("id", 0);
  nlohmann::json doc = mesh_to_json(with_hole);
  doc["attributes"][0]["values"][8] = 4;
  CHECK_THROWS_WITH_AS(mesh_from_json(doc, "bad.json"), doctest::Contains("attributes[0].values[8]"),
                       IoError);
}

TEST_CASE("attributes: old JSON with face_points loads into the face_point attribute") {
  // The layout written before attributes existed: "face_points", one [x, y, z] or null per face slot.
  nlohmann::json doc = mesh_to_json(test::cube());
  doc["face_points"] = nlohmann::json::array();
  for (int f = 0; f < 6; ++f)
    doc["face_points"].push_back(f == 2 ? nlohmann::json{0.5, -1, 2} : nlohmann::json(nullptr));
  const Mesh old = mesh_from_json(doc, "old.json");
  CHECK(face_point(old, FaceId(2)) == glm::dvec3(0.5, -1, 2));
  CHECK_FALSE(face_point(old, FaceId(3)).has_value());
  // The same as setting the point through the new API, hash included.
  Mesh set = test::cube();
  set_face_point(set, FaceId(2), glm::dvec3(0.5, -1, 2));
  CHECK(old == set);
  CHECK(mesh_hash(old) == mesh_hash(set));
  // The face_point attribute given both ways is refused.
  nlohmann::json twice = mesh_to_json(set);
  twice["face_points"] = doc["face_points"];
  CHECK_THROWS_WITH_AS(mesh_from_json(twice, "twice.json"), doctest::Contains("face_point"), IoError);
}

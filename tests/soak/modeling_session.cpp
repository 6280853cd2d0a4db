// A randomized modeling session over every registered operation (but clear_history, which would make the
// start unreachable), with groups, undo, redo and schemes. Parameters are drawn from each operation's
// declaration, so an operation added to the registry is soaked with no change here; handles are mostly live,
// sometimes removed or out of range, values sometimes out of range, so refusals are exercised too.
//
//   dlfl_soak [OPS [SEED]]      (default 20000 ops, seed 1; DLFL_SOAK_OPS overrides OPS)
//
// Checked: only dlfl::Error is ever thrown; a refused op leaves mesh and log as they were (checked on a
// sample); the mesh validates every 1000 ops; the log replays to the same hash; undoing everything gives the
// start mesh back. CTest runs the short form (label "soak"); `DLFL_SOAK_OPS=1000000 ctest -L soak` is the
// long run.

#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/operations/operation.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/validate.h>

namespace {

using namespace dlfl;

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "soak: %s\n", what.c_str());
  std::exit(1);
}

Mesh cube() {
  PolygonSoup soup;
  soup.positions = {{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, -1},
                    {-1, -1, 1},  {1, -1, 1},  {-1, 1, 1},  {1, 1, 1}};
  for (auto f : {std::initializer_list<std::uint32_t>{0, 2, 3, 1},
                 {4, 5, 7, 6},
                 {0, 1, 5, 4},
                 {2, 6, 7, 3},
                 {0, 4, 6, 2},
                 {1, 3, 7, 5}})
    soup.add_face(f);
  return build_mesh(soup);
}

class Session {
 public:
  explicit Session(unsigned seed) : random_(seed) {}

  // Mostly a live handle of the kind, sometimes any slot up to two past the capacity (removed or missing).
  template <class H>
  H handle(const Mesh& m) {
    const std::uint32_t capacity = m.capacity(element_kind_v<H>);
    if (chance(0.9)) {
      for (int tries = 0; tries < 8 && capacity > 0; ++tries) {
        const H h(pick(capacity));
        if (m.is_alive(h)) return h;
      }
    }
    return H(pick(capacity + 2));
  }

  // A list of 1 to 6 handles drawn as `handle` draws one (so sometimes with a removed one or a repeat).
  template <class H>
  std::vector<H> handles(const Mesh& m) {
    std::vector<H> out(1 + pick(6));
    for (H& h : out) h = handle<H>(m);
    return out;
  }

  // For a handle parameter: a handle of the kind `type` names (ParamType::face: a FaceId), or a list of them
  // for a list type (ParamType::faces). Empty for the other types.
  Value handle_value(ParamType type, const Mesh& m) {
    Value out;
    const auto draw = [&](auto kind, ParamType one, ParamType list) {
      using H = decltype(kind);
      if (type == one) out = handle<H>(m);
      if (type == list) out = handles<H>(m);
    };
    draw(VertexId(), ParamType::vertex, ParamType::vertices);
    draw(EdgeId(), ParamType::edge, ParamType::edges);
    draw(FaceId(), ParamType::face, ParamType::faces);
    draw(CornerId(), ParamType::corner, ParamType::corners);
    return out;
  }

  Value value_for(const ParamSpec& p, const Mesh& m) {
    switch (p.type) {
      case ParamType::boolean:
        return chance(0.5);
      case ParamType::integer: {
        const double lo = std::isfinite(p.min) ? p.min : -3,
                     hi = std::isfinite(p.max) ? std::min(p.max, lo + 4) : 5;
        return static_cast<std::int64_t>(lo + pick(static_cast<std::uint32_t>(hi - lo + 1)));
      }
      case ParamType::number: {
        const double lo = std::isfinite(p.min) ? p.min : -2, hi = std::isfinite(p.max) ? p.max : 2;
        return chance(0.95) ? lo + (hi - lo) * unit() : hi + 1;  // sometimes out of range
      }
      case ParamType::text:
        if (!p.keywords.empty()) return p.keywords[pick(static_cast<std::uint32_t>(p.keywords.size()))];
        if (p.name == "scheme") return schemes_[pick(static_cast<std::uint32_t>(schemes_.size()))];
        return std::string(chance(0.5) ? "weight" : "tag");
      case ParamType::point: {
        // Drawn in braces, which evaluate left to right: the arguments of a call have no fixed order, and
        // gcc and clang would draw different sessions from one seed.
        const double x[] = {2 * unit() - 1, 2 * unit() - 1, 2 * unit() - 1};
        return glm::dvec3(x[0], x[1], x[2]);
      }
      case ParamType::vertex:
      case ParamType::edge:
      case ParamType::face:
      case ParamType::corner:
      case ParamType::vertices:
      case ParamType::edges:
      case ParamType::faces:
      case ParamType::corners:
        return handle_value(p.type, m);
      case ParamType::numbers:
        return chance(0.5) ? std::vector<double>{unit()} : std::vector<double>{unit(), unit(), unit()};
      case ParamType::points: {
        std::vector<glm::dvec3> points(3 + pick(4));
        for (auto& q : points) q = {unit(), unit(), unit()};
        return points;
      }
      case ParamType::mesh:
        return std::make_shared<const Mesh>(cube());
      case ParamType::params:
        break;
    }
    return Value();  // left out: its default, or refused as missing
  }

  // The parameters of one op, drawn from its declaration; optional ones are sometimes left out.
  Params params_for(const OperationSpec& op, const Mesh& m) {
    Params p;
    // delete_vertex removes point spheres only: drawn like other vertices it almost always hits one with
    // edges and is refused, so that whether it ever succeeds would be luck. Mostly it gets a point sphere.
    if (op.name == "delete_vertex" && chance(0.7)) {
      std::vector<VertexId> spheres;
      for (VertexId v : m.vertices())
        if (m.is_point_sphere(v)) spheres.push_back(v);
      if (!spheres.empty()) return {{"vertex", spheres[pick(static_cast<std::uint32_t>(spheres.size()))]}};
    }
    for (const ParamSpec& spec : op.params) {
      if ((spec.is_optional || !spec.default_value.empty()) && chance(0.4)) continue;
      if (op.name == "subdivide" && spec.name == "iterations") {
        p[spec.name] = std::int64_t{1};
        continue;
      }
      Value v = value_for(spec, m);
      if (!v.empty()) p[spec.name] = std::move(v);
    }
    return p;
  }

  bool chance(double p) { return unit() < p; }
  double unit() { return std::uniform_real_distribution<double>(0, 1)(random_); }
  std::uint32_t pick(std::uint32_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random_);
  }

 private:
  std::mt19937 random_;
  std::vector<std::string> schemes_ = scheme_names();
};

}  // namespace

int main(int argc, char** argv) {
  long ops_count = argc > 1 ? std::atol(argv[1]) : 20000;
  if (const char* env = std::getenv("DLFL_SOAK_OPS")) ops_count = std::atol(env);
  const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atol(argv[2])) : 1;
  Session session(seed);

  std::vector<const OperationSpec*> ops;
  for (const OperationSpec& op : operations())
    if (op.name != "clear_history" && op.name != "load") ops.push_back(&op);  // load reads files
  Editor editor;
  editor.set_mesh(cube());
  const Mesh start = editor.mesh();
  long applied = 0, refused = 0;
  std::map<std::string, long> applied_by_op;
  for (long i = 0; i < ops_count; ++i) {
    const OperationSpec& op = *ops[session.pick(static_cast<std::uint32_t>(ops.size()))];
    // Schemes, and the operations that grow the whole mesh (shells and frames, high genus, hexagonalize),
    // only on small meshes, so that the session stays quick; bigger meshes get undone instead.
    static const std::set<std::string> whole_mesh_growth = {
        "subdivide", "crust", "rind", "wireframe", "columns", "sierpinski", "menger", "hexagonalize"};
    if (whole_mesh_growth.count(op.name) && editor.mesh().num_corners() > 2000) {
      try {
        (void)editor.undo();
      } catch (const Error&) {  // inside an open group
      }
      continue;
    }
    // Drawn freely, groups nest like a random walk and stay open for most of a long session, where undo and
    // redo are refused, so that whether redo ever succeeds is luck. Two deep, a begin_group closes one.
    if (op.name == "begin_group" && editor.group_depth() >= 2) {
      editor.end_group();
      continue;
    }
    // The first entry set the start mesh: an undo of it would make the final check meaningless.
    if (op.name == "undo" && editor.undo_history().size() <= 1) continue;
    const Params params = session.params_for(op, editor.mesh());
    const bool compare = i % 97 == 0;
    const Mesh before = compare ? editor.mesh() : Mesh();
    const std::size_t logged = editor.log().size();
    try {
      editor.apply(op.name, params);
      ++applied;
      ++applied_by_op[op.name];
    } catch (const Error&) {
      ++refused;
      if (editor.log().size() != logged)
        fail("op " + std::to_string(i) + " (" + op.name + ") was refused but logged");
      if (compare && !(editor.mesh() == before))
        fail("op " + std::to_string(i) + " (" + op.name + ") was refused but changed the mesh");
    } catch (const std::exception& e) {
      fail("op " + std::to_string(i) + " (" + op.name + ") threw a non-dlfl exception: " + e.what());
    }
    if (i % 1000 == 999) {
      const ValidationReport report = validate(editor.mesh(), 1);
      if (!report.valid()) fail("after op " + std::to_string(i) + ": " + report.violations.front().message);
    }
  }
  // A session long enough must have run every operation at least once, or the soak would not cover it.
  if (ops_count >= 5000) {
    for (const OperationSpec* op : ops)
      if (applied_by_op[op->name] == 0)
        fail(op->name + " never succeeded: its parameters need a better draw");
  }
  while (editor.group_depth() > 0) editor.end_group();
  const std::string final_hash = mesh_hash(editor.mesh());
  if (mesh_hash(replay_log(log_text(editor)).mesh()) != final_hash) fail("the log replays to another mesh");
  // Every entry but the first, which loaded the start mesh.
  for (std::size_t n = editor.undo_history().size(); n > 1; --n) (void)editor.undo();
  if (!(editor.mesh() == start)) fail("undoing everything does not give the start mesh back");
  std::printf(
      "soak: %ld ops (%ld applied, %ld refused), seed %u; log replays to %s; undo of all gives the start\n",
      ops_count, applied, refused, seed, final_hash.c_str());
  return 0;
}

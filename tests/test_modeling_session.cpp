// A randomized modeling session of legal operations: the modeling operations of docs/modeling.md with
// arguments drawn where they apply (surface faces, edges between two faces, corners of different faces),
// mixed with the Euler operators, a scheme step, groups, undo and redo. The mesh is validated as the session
// goes, the log replays to the same hash, and undoing everything gives the start back. (The soak,
// tests/soak/, draws arguments blindly from the declarations; this one makes sure every operation is
// exercised where it succeeds.)

#include <doctest/doctest.h>

#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/validate.h>

#include "modeling_meshes.h"

namespace {

using namespace dlfl;

class Draw {
 public:
  explicit Draw(unsigned seed) : random_(seed) {}

  std::uint32_t below(std::uint32_t n) {
    return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random_);
  }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(random_) < p; }
  double between(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random_); }

  template <class H>
  H live(const Mesh& m) {
    for (;;) {
      const H h(below(m.capacity(element_kind_v<H>)));
      if (m.is_alive(h)) return h;
    }
  }
  FaceId surface_face(const Mesh& m) {
    for (int tries = 0; tries < 1000; ++tries) {
      const FaceId f = live<FaceId>(m);
      if (!m.is_hole(f) && m.size(f) >= 3) return f;
    }
    return live<FaceId>(m);
  }
  FaceId hole_face(const Mesh& m) {
    for (int tries = 0; tries < 200; ++tries) {
      const FaceId f = live<FaceId>(m);
      if (m.is_hole(f)) return f;
    }
    return live<FaceId>(m);
  }
  // A corner with an edge, in a surface face.
  CornerId surface_corner(const Mesh& m) { return m.first_corner(surface_face(m)); }
  EdgeId edge(const Mesh& m) { return live<EdgeId>(m); }

 private:
  std::mt19937 random_;
};

using Drawer = std::function<Params(const Mesh&, Draw&)>;

// The operations of the session with the draw of their arguments (names and fields as docs/modeling.md).
std::vector<std::pair<std::string, Drawer>> legal_operations() {
  return {
      {"collapse_edge",
       [](const Mesh& m, Draw& d) {
         return Params{{"edge", d.edge(m)}, {"cleanup", d.chance(0.5)}};
       }},
      {"splice_corners",
       [](const Mesh& m, Draw& d) {
         const FaceId f = d.surface_face(m);
         const CornerId c = m.first_corner(f);
         // Two corners of one face, two apart: their vertices are not joined by an edge of the face.
         return Params{{"corner1", c}, {"corner2", m.next(m.next(c))}};
       }},
      {"divide_edge",
       [](const Mesh& m, Draw& d) {
         return Params{{"edge", d.edge(m)}, {"segments", std::int64_t(1 + d.below(4))}};
       }},
      {"flip_edge",
       [](const Mesh& m, Draw& d) {
         return Params{{"edge", d.edge(m)}};
       }},
      {"stellate_face",
       [](const Mesh& m, Draw& d) {
         return Params{{"face", d.surface_face(m)}, {"height", d.between(-0.2, 0.5)}};
       }},
      {"subdivide_face",
       [](const Mesh& m, Draw& d) {
         return Params{{"face", d.surface_face(m)}, {"style", d.chance(0.5) ? "quads" : "triangles"}};
       }},
      {"triangulate",
       [](const Mesh& m, Draw& d) {
         return Params{{"faces", std::vector<FaceId>{d.surface_face(m)}}};
       }},
      {"reverse_orientation", [](const Mesh&, Draw&) { return Params{}; }},
      {"make_hole",
       [](const Mesh& m, Draw& d) {
         return Params{{"face", d.surface_face(m)}};
       }},
      {"fill_hole",
       [](const Mesh& m, Draw& d) {
         return Params{{"face", d.hole_face(m)}};
       }},
      {"transform",
       [](const Mesh&, Draw& d) {
         return Params{{"translate", glm::dvec3(d.between(-1, 1), 0, 0)},
                       {"rotate_degrees", d.between(-90, 90)},
                       {"scale", glm::dvec3(d.between(0.5, 2))}};
       }},
      {"connect_edges",
       [](const Mesh& m, Draw& d) {
         return Params{{"corner1", d.surface_corner(m)}, {"corner2", d.surface_corner(m)}};
       }},
      {"connect_faces",
       [](const Mesh& m, Draw& d) {
         return Params{{"face1", d.surface_face(m)},
                       {"face2", d.surface_face(m)},
                       {"segments", std::int64_t(1 + d.below(4))},
                       {"twist", std::int64_t(d.below(3))}};
       }},
      {"extrude_face",
       [](const Mesh& m, Draw& d) {
         static const char* styles[] = {"cubical",         "doo-sabin",    "octahedral",  "stellate",
                                        "double-stellate", "dodecahedral", "icosahedral", "dome"};
         return Params{{"face", d.surface_face(m)},
                       {"distance", d.between(0.1, 1)},
                       {"segments", std::int64_t(1 + d.below(3))},
                       {"style", styles[d.below(8)]}};
       }},
      {"inset_face",
       [](const Mesh& m, Draw& d) {
         return Params{{"face", d.surface_face(m)}, {"amount", d.between(0.1, 0.9)}};
       }},
      {"insert_edge",
       [](const Mesh& m, Draw& d) {
         const CornerId c = d.surface_corner(m);
         return Params{{"corner1", c}, {"corner2", m.next(m.next(c))}};
       }},
      {"subdivide_edge",
       [](const Mesh& m, Draw& d) {
         return Params{{"edge", d.edge(m)}};
       }},
  };
}

}  // namespace

TEST_CASE("a random session of legal modeling operations validates, replays and undoes exactly") {
  for (const unsigned seed : {1u, 2u}) {
    CAPTURE(seed);
    Draw draw(seed);
    const auto ops = legal_operations();
    Editor editor;
    editor.set_mesh(test::cube());
    const Mesh start = editor.mesh();
    std::map<std::string, int> applied;
    int undos = 0, redos = 0, groups = 0, schemes = 0;
    for (int i = 0; i < 3000; ++i) {
      const std::uint32_t roll = draw.below(100);
      try {
        if (roll < 4) {
          undos += editor.undo();
        } else if (roll < 7) {
          redos += editor.redo();
        } else if (roll < 9 && editor.group_depth() < 2) {
          editor.begin_group("group " + std::to_string(i));
          ++groups;
        } else if (roll < 11 && editor.group_depth() > 0) {
          editor.end_group();
        } else if (roll < 12 && editor.mesh().num_corners() < 600) {
          editor.subdivide(draw.chance(0.5) ? "catmull-clark" : "doo-sabin");
          ++schemes;
        } else {
          const auto& [name, drawer] = ops[draw.below(static_cast<std::uint32_t>(ops.size()))];
          // Big meshes get an undo instead, so that the session stays quick.
          if (editor.mesh().num_corners() > 20000) {
            if (editor.group_depth() == 0) (void)editor.undo();
            continue;
          }
          const Params params = drawer(editor.mesh(), draw);
          try {
            editor.apply(name, params);
            ++applied[name];
          } catch (const ParameterError&) {
            // A legal-looking draw that the operation refuses (a link condition, a self-loop): fine, and
            // the mesh is unchanged (checked by the operation tests).
          }
        }
      } catch (const InvalidArgument&) {
        // undo or redo inside an open group
      }
      if (i % 250 == 249) {
        const ValidationReport report = validate(editor.mesh(), 1);
        REQUIRE_MESSAGE(report.valid(), "after step ", i, ": ", report.violations.front().message);
      }
    }
    for (const auto& [name, drawer] : ops) {
      const auto& name_ = name;  // clang 14 cannot capture a structured binding
      CAPTURE(name_);
      CHECK(applied[name] > 0);
    }
    CHECK(undos > 0);
    CHECK(redos > 0);
    CHECK(groups > 0);
    CHECK(schemes > 0);
    while (editor.group_depth() > 0) editor.end_group();
    CHECK(mesh_hash(replay_log(log_text(editor)).mesh()) == mesh_hash(editor.mesh()));
    // Every entry but the first, which set the cube.
    for (std::size_t n = editor.undo_history().size(); n > 1; --n) (void)editor.undo();
    CHECK(editor.mesh() == start);
  }
}

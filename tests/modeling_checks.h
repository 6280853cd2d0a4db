#pragma once
// Checks shared by the tests of the modeling operations: volumes, counts, the editor round trip and refusals.

#include <doctest/doctest.h>

#include <cstddef>
#include <glm/geometric.hpp>
#include <ostream>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/operation.h>

#include "modeling_meshes.h"
#include "test_helpers.h"

namespace dlfl::test {

/// The volume the surface faces enclose (fans from each first corner): positive if closed and outward.
inline double signed_volume(const Mesh& m) {
  double volume = 0;
  for (FaceId f : surface_faces(m)) {
    const CornerId first = m.first_corner(f);
    const glm::dvec3 p0 = m.position(m.vertex(first));
    for (CornerId c = m.next(first); m.next(c) != first; c = m.next(c)) {
      volume += glm::dot(p0, glm::cross(m.position(m.vertex(c)), m.position(m.vertex(m.next(c))))) / 6.0;
    }
  }
  return volume;
}

/// The numbers of vertices, edges and faces (hole faces included) of a mesh.
struct Counts {
  long v = 0, e = 0, f = 0;
  bool operator==(const Counts&) const = default;
  friend std::ostream& operator<<(std::ostream& os, const Counts& c) {
    return os << "V=" << c.v << " E=" << c.e << " F=" << c.f;
  }
};

/// The counts of `m`.
inline Counts counts(const Mesh& m) {
  return {long(m.num_vertices()), long(m.num_edges()), long(m.num_faces())};
}

/// V - E + F, hole faces counted as faces.
inline long euler_characteristic(const Mesh& m) {
  return long(m.num_vertices()) - long(m.num_edges()) + long(m.num_faces());
}

/// Applies `op` via an editor: valid, undo == with same hash, redo == with same hash, log replays; the
/// result.
inline Mesh check_editor_round_trip(const Mesh& start, const std::string& op, const Params& params,
                                    Params* outputs = nullptr) {
  Editor ed;
  ed.set_mesh(start);
  const Mesh before = ed.mesh();
  const std::string before_hash = mesh_hash(before);
  const Params out = ed.apply(op, params);
  const Mesh after = ed.mesh();
  require_valid(after);
  REQUIRE(ed.undo());
  CHECK(ed.mesh() == before);
  CHECK(mesh_hash(ed.mesh()) == before_hash);
  REQUIRE(ed.redo());
  CHECK(ed.mesh() == after);
  CHECK(mesh_hash(ed.mesh()) == mesh_hash(after));
  const auto path = scratch("round_trip_" + op + ".json");
  write_log(ed, path);
  CHECK(mesh_hash(replay_log_file(path).mesh()) == mesh_hash(after));
  if (outputs) *outputs = out;
  return after;
}

/// Checks `op` is refused naming `parameter`, message "op: parameter <name>...", mesh and log unchanged.
inline std::string check_refusal(const Mesh& start, const std::string& op, const Params& params,
                                 const std::string& parameter) {
  Editor ed;
  ed.set_mesh(start);
  const Mesh before = ed.mesh();
  const std::size_t logged = ed.log().size();
  std::string message, named;
  bool refused = false;
  try {
    ed.apply(op, params);
  } catch (const ParameterError& e) {
    refused = true;
    message = e.what();
    named = e.parameter();
  }
  CAPTURE(message);
  CHECK(refused);
  CHECK(named == parameter);
  CHECK(message.rfind(op + ": parameter " + parameter, 0) == 0);
  CHECK(ed.mesh() == before);
  CHECK(ed.log().size() == logged);
  return message;
}

}  // namespace dlfl::test

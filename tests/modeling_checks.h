#pragma once
// Checks shared by the tests of the modeling operations: volumes, counts, a check run on every modeling mesh,
// the editor round trip, the counts an operation changes and refusals.

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

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

/// Runs `check` on each of `meshes` with the mesh's name captured for the messages of failing checks:
/// `check(mesh)`, or `check(name, mesh)` if it takes the name too.
template <class Check>
void for_each_mesh(const std::vector<ModelingMesh>& meshes, Check&& check) {
  for (const ModelingMesh& m : meshes) {
    CAPTURE(m.name);
    if constexpr (std::is_invocable_v<Check&, const Mesh&>) {
      check(m.mesh);
    } else {
      check(m.name, m.mesh);
    }
  }
}

/// for_each_mesh() on modeling_meshes().
template <class Check>
void for_each_modeling_mesh(Check&& check) {
  for_each_mesh(modeling_meshes(), check);
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

/// A change of the counts: vertices, edges and faces, and of those the hole faces.
struct Delta {
  long v = 0, e = 0, f = 0, holes = 0;
};

/// A mesh an operation left and the outputs it gave.
struct Applied {
  Mesh mesh;
  Params out;
};

/// Applies `op` through check_editor_round_trip, then checks what every operation that keeps the topology
/// type must: the counts changed by `delta`, the Euler characteristic kept and, if `check_orientation`, a
/// closed mesh's volume keeping its sign (no face turned inside out). Returns the mesh after and the outputs.
inline Applied apply_and_check(const Mesh& start, const std::string& op, const Params& params, Delta delta,
                               bool check_orientation = true) {
  Params out;
  const Mesh after = check_editor_round_trip(start, op, params, &out);
  CHECK(long(after.num_vertices()) == long(start.num_vertices()) + delta.v);
  CHECK(long(after.num_edges()) == long(start.num_edges()) + delta.e);
  CHECK(long(after.num_faces()) == long(start.num_faces()) + delta.f);
  CHECK(long(after.num_hole_faces()) == long(start.num_hole_faces()) + delta.holes);
  CHECK(euler_characteristic(after) == euler_characteristic(start));
  if (check_orientation && start.num_hole_faces() == 0 && std::abs(signed_volume(start)) > 1e-9)
    CHECK((signed_volume(after) > 0) == (signed_volume(start) > 0));
  return {after, out};
}

/// What an apply expected to be refused raised: whether it was refused, the parameter its ParameterError
/// names ("(accepted)" if none) and its message.
struct Refusal {
  bool refused = false;
  std::string parameter = "(accepted)";
  std::string message;
};

/// Applies `op` on `ed` expecting a ParameterError whose message names the operation, then the parameter, and
/// contains `message_part`; checks the mesh and the log stay as they were. Returns what was raised.
inline Refusal refusal(Editor& ed, const std::string& op, const Params& params,
                       const std::string& message_part = {}) {
  const Mesh before = ed.mesh();
  const std::size_t logged = ed.log().size();
  Refusal r;
  try {
    ed.apply(op, params);
  } catch (const ParameterError& e) {
    r = {true, e.parameter(), e.what()};
  }
  const std::string& message = r.message;
  CAPTURE(message);
  if (r.refused) {
    // The operation first, then the parameter: "op: parameter <name> ...", or for a choice between two
    // parameters "op: give exactly one of parameters <name> and <other> ...".
    CHECK(message.rfind(op + ": ", 0) == 0);
    CHECK(message.find(r.parameter) != std::string::npos);
    CHECK((message.rfind(op + ": parameter " + r.parameter, 0) == 0 ||
           message.rfind(op + ": give exactly one of parameters " + r.parameter + " and ", 0) == 0));
    if (!message_part.empty()) CHECK(message.find(message_part) != std::string::npos);
  }
  CHECK(ed.mesh() == before);
  CHECK(ed.log().size() == logged);
  return r;
}

/// refusal() in an editor holding `start`.
inline Refusal refusal(const Mesh& start, const std::string& op, const Params& params,
                       const std::string& message_part = {}) {
  Editor ed;
  ed.set_mesh(start);
  return refusal(ed, op, params, message_part);
}

/// The parameter a refused apply on `ed` names, "(accepted)" if it is not refused (see refusal()).
inline std::string refused_parameter(Editor& ed, const std::string& op, const Params& params,
                                     const std::string& message_part = {}) {
  return refusal(ed, op, params, message_part).parameter;
}

/// The parameter a refused apply to `start` names, "(accepted)" if it is not refused (see refusal()).
inline std::string refused_parameter(const Mesh& start, const std::string& op, const Params& params,
                                     const std::string& message_part = {}) {
  return refusal(start, op, params, message_part).parameter;
}

/// Checks `op` is refused naming `parameter` (see refusal()), the message containing `message_part`, mesh and
/// log unchanged; the message.
inline std::string check_refusal(const Mesh& start, const std::string& op, const Params& params,
                                 const std::string& parameter, const std::string& message_part = {}) {
  const Refusal r = refusal(start, op, params, message_part);
  const std::string& message = r.message;
  CAPTURE(message);
  CHECK(r.refused);
  CHECK(r.parameter == parameter);
  return r.message;
}

}  // namespace dlfl::test

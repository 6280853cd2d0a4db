#pragma once
// What the modelling examples share: finding a face by where it is, and at the end: reporting the model,
// write it with its log, and check that the log replays to the same mesh and that undo gives the start back.

#include <dlfl/dlfl.h>

#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <string>

namespace example {

/// The surface face whose centroid is nearest to `target` (the first in handle order on a tie).
inline dlfl::FaceId face_nearest(const dlfl::Mesh& mesh, const glm::dvec3& target) {
  dlfl::FaceId best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (dlfl::FaceId f : dlfl::surface_faces(mesh)) {
    const double d = glm::distance(dlfl::face_centroid(mesh, f), target);
    if (d < best_distance) best = f, best_distance = d;
  }
  return best;
}

/// Prints the editor's mesh (V, E, F, genus), writes it to OUT/NAME.obj and its log to OUT/NAME.log.json, and
/// checks that the log replays to the same mesh and that `steps` undos give `start` back. True when all of
/// that holds and the mesh is one valid component of genus `genus` with V, E and F as given.
inline bool report_model(dlfl::Editor& editor, const std::string& out, const std::string& name,
                         const dlfl::Mesh& start, int steps, const dlfl::MeshCounts& expected, long genus) {
  const dlfl::Mesh mesh = editor.mesh();
  const dlfl::ValidationReport report = dlfl::validate(mesh);
  const long found = report.valid() && report.components.size() == 1 ? report.components[0].genus : -1;
  std::printf("V %zu, E %zu, F %zu, genus %ld\n", mesh.num_vertices(), mesh.num_edges(), mesh.num_faces(),
              found);
  dlfl::write_mesh(mesh, out + "/" + name + ".obj");
  dlfl::write_log(editor, out + "/" + name + ".log.json");

  const bool replays =
      dlfl::mesh_hash(dlfl::replay_log(dlfl::log_text(editor)).mesh()) == dlfl::mesh_hash(mesh);
  for (int i = 0; i < steps; ++i) editor.undo();
  const bool undone = editor.mesh() == start;
  std::printf("log replays to the same mesh: %s; undo gives the start back: %s\n", replays ? "yes" : "no",
              undone ? "yes" : "no");
  return found == genus && dlfl::counts_of(mesh) == expected && replays && undone;
}

}  // namespace example

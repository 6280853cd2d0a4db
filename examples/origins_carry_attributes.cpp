// A user attribute carried across a subdivision step by the scheme's origin map: each face of the input
// has a material number; after Catmull-Clark each quad takes the material of the face it stems from.
// Usage: example_origins_carry_attributes [DATA_DIR]
#include <dlfl/dlfl.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : "data";
  const dlfl::Mesh cube = dlfl::read_mesh(data + "/cube.obj");
  dlfl::FaceData<int> material(cube, 0);
  for (dlfl::FaceId f : cube.faces()) material[f] = static_cast<int>(f.index()) % 3;

  dlfl::Origins origins;
  const dlfl::Mesh fine = dlfl::apply_scheme(cube, "catmull-clark", {}, &origins);
  dlfl::FaceData<int> fine_material(fine, -1);
  int counts[3] = {0, 0, 0};
  for (dlfl::FaceId q : fine.faces()) {
    // A Catmull-Clark quad stems from a corner of the input: the corner's face gives the material.
    const dlfl::Origin o = origins.of(q);
    const dlfl::FaceId from = o.kind == dlfl::Origin::Kind::corner ? cube.face(o.corner()) : o.face();
    fine_material[q] = material[from];
    ++counts[fine_material[q]];
  }
  std::printf("materials 0, 1, 2 on %d, %d, %d quads\n", counts[0], counts[1], counts[2]);
  // Each cube face becomes 4 quads and each material is on 2 faces.
  return counts[0] == 8 && counts[1] == 8 && counts[2] == 8 ? 0 : 1;
}

#pragma once
// The small meshes that the scheme and operation harnesses work on, built once.

#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/parsed_polygons.h>
#include <dlfl/mesh.h>

#include "fuzz_common.h"

namespace dlfl::fuzz {

inline const Mesh& cube() {
  static const Mesh mesh = build_mesh(io_detail::parse_obj_text(cube_obj, "cube"), "cube");
  return mesh;
}

inline const Mesh& tetrahedron() {
  static const Mesh mesh =
      build_mesh(io_detail::parse_obj_text(tetrahedron_obj, "tetrahedron"), "tetrahedron");
  return mesh;
}

}  // namespace dlfl::fuzz

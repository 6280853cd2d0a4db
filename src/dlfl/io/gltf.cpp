// glTF 2.0 binary: see gltf.h. The layout of the BIN chunk: positions, normals, face indices (one per
// vertex), then the triangles' vertex indices, each a tightly packed buffer view of 4-byte components.

#include <dlfl/io/gltf.h>

#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>

#include <dlfl/io/detail/gltf_file.h>
#include <dlfl/io/detail/text_io.h>

namespace dlfl {
namespace io_detail {
namespace {

// The constants of the glTF 2.0 specification.
constexpr std::uint32_t magic = 0x46546C67;       // "glTF"
constexpr std::uint32_t json_chunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t bin_chunk = 0x004E4942;   // "BIN\0"
constexpr int float_type = 5126, uint32_type = 5125;
constexpr int array_buffer = 34962, element_array_buffer = 34963;
constexpr int triangles_mode = 4;
// The largest integer from which every smaller one is exact in a float32.
constexpr std::uint32_t exact_float_integers = 1u << 24;

constexpr std::size_t padded(std::size_t bytes) { return (bytes + 3) / 4 * 4; }

glm::vec3 float_normal(const glm::dvec3& n) {
  return n == glm::dvec3(0.0) ? glm::vec3(0, 0, 1) : glm::vec3(n);  // glTF requires unit normals
}

}  // namespace

GlbFile::GlbFile(const Mesh& mesh, const std::string& file)
    : mesh_(mesh), triangles_(mesh_triangles(mesh, file)) {
  const MeshTriangles& t = triangles_;
  const std::size_t vertices = t.corners.size(), indices = t.triangles.size();
  for (FaceId f : t.faces) {
    if (f.index() >= exact_float_integers) {
      throw IoError(to_string(f) +
                        ": face handle indices from 2^24 on have no exact float32, in which glTF "
                        "stores the _FACE_INDEX attribute (compact the mesh, or write another format)",
                    file);
    }
  }
  glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  for (CornerId c : t.corners) {
    const glm::vec3 p(mesh.position(mesh.vertex(c)));
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const std::size_t vec3_bytes = 12 * vertices, face_bytes = 4 * vertices, index_bytes = 4 * indices;
  bin_bytes_ = 2 * vec3_bytes + face_bytes + index_bytes;
  using nlohmann::json;
  auto view = [](std::size_t offset, std::size_t bytes, int target) {
    return json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}};
  };
  auto accessor = [](int view_index, int type, std::size_t count, const char* shape) {
    return json{{"bufferView", view_index}, {"componentType", type}, {"count", count}, {"type", shape}};
  };
  json position = accessor(0, float_type, vertices, "VEC3");
  // As floats, widened exactly to doubles: the values a reader compares with the data.
  position["min"] = {double(low.x), double(low.y), double(low.z)};
  position["max"] = {double(high.x), double(high.y), double(high.z)};
  const json doc = {
      {"asset", {{"version", "2.0"}, {"generator", "dlfl"}}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", {0}}}})},
      {"nodes", json::array({{{"mesh", 0}}})},
      {"meshes",
       json::array({{{"primitives",
                      json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"_FACE_INDEX", 2}}},
                                    {"indices", 3},
                                    {"mode", triangles_mode}}})}}})},
      {"buffers", json::array({{{"byteLength", bin_bytes_}}})},
      {"bufferViews",
       json::array({view(0, vec3_bytes, array_buffer), view(vec3_bytes, vec3_bytes, array_buffer),
                    view(2 * vec3_bytes, face_bytes, array_buffer),
                    view(2 * vec3_bytes + face_bytes, index_bytes, element_array_buffer)})},
      {"accessors", json::array({position, accessor(1, float_type, vertices, "VEC3"),
                                 accessor(2, float_type, vertices, "SCALAR"),
                                 accessor(3, uint32_type, indices, "SCALAR")})},
  };
  json_ = doc.dump();
  json_.resize(padded(json_.size()), ' ');
}

void GlbFile::write(std::ostream& out) const {
  const MeshTriangles& t = triangles_;
  const std::size_t bin_padded = padded(bin_bytes_);
  const std::size_t total = 12 + 8 + json_.size() + 8 + bin_padded;
  BlockWriter w(out);
  w.binary(magic);
  w.binary(std::uint32_t{2});
  w.binary(static_cast<std::uint32_t>(total));
  w.binary(static_cast<std::uint32_t>(json_.size()));
  w.binary(json_chunk);
  w.text(json_);
  w.binary(static_cast<std::uint32_t>(bin_padded));
  w.binary(bin_chunk);
  auto vec3 = [&](const glm::vec3& v) {
    w.binary(v.x);
    w.binary(v.y);
    w.binary(v.z);
  };
  for (CornerId c : t.corners) vec3(glm::vec3(mesh_.position(mesh_.vertex(c))));
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    const glm::vec3 n = float_normal(t.normals[f]);
    for (std::uint32_t i = t.first_corner[f]; i < t.first_corner[f + 1]; ++i) vec3(n);
  }
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    const auto index = static_cast<float>(t.faces[f].index());
    for (std::uint32_t i = t.first_corner[f]; i < t.first_corner[f + 1]; ++i) w.binary(index);
  }
  for (std::uint32_t i : t.triangles) w.binary(i);
  for (std::size_t i = bin_bytes_; i < bin_padded; ++i) w.put('\0');
  w.flush();
}

}  // namespace io_detail

void write_glb(std::ostream& out, const Mesh& mesh, const std::string& name) {
  io_detail::GlbFile(mesh, name).write(out);
}

}  // namespace dlfl

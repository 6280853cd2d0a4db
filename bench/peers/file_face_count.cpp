// Counting a mesh file's faces (file_face_count.h).

#include "file_face_count.h"

#include <fstream>
#include <vector>

namespace dlfl::bench {

namespace {

std::optional<std::size_t> ply_faces(std::ifstream& in) {
  std::string line;
  while (std::getline(in, line) && line != "end_header" && line != "end_header\r") {
    if (line.rfind("element face ", 0) == 0) return std::size_t(std::stoull(line.substr(13)));
  }
  return std::nullopt;
}

// Lines starting with "f ", counted in large blocks (an OBJ of 16M faces is over a gigabyte).
std::size_t obj_faces(std::ifstream& in) {
  std::vector<char> block(1 << 20);
  std::size_t faces = 0;
  int column = 0;         // 0: at a line's first character, 1: second, 2: further
  bool starts_f = false;  // the current line started with 'f'
  while (in) {
    in.read(block.data(), std::streamsize(block.size()));
    const std::size_t n = std::size_t(in.gcount());
    for (std::size_t i = 0; i < n; ++i) {
      const char c = block[i];
      if (c == '\n') {
        column = 0;
        continue;
      }
      if (column == 0) starts_f = c == 'f';
      if (column == 1 && starts_f && (c == ' ' || c == '\t')) ++faces;
      if (column < 2) ++column;
    }
  }
  return faces;
}

}  // namespace

std::optional<std::size_t> file_face_count(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".ply") == 0) return ply_faces(in);
  return obj_faces(in);
}

}  // namespace dlfl::bench

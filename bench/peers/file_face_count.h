#pragma once
// The number of faces in a PLY or OBJ file, read without parsing the geometry: the sanity check of
// dlfl_bench_end_to_end that every program wrote the whole result.

#include <cstddef>
#include <optional>
#include <string>

namespace dlfl::bench {

/// PLY: the count in the header's "element face" line. OBJ: the number of lines that start with "f ".
/// Nothing if the file cannot be read or a PLY header has no face element.
std::optional<std::size_t> file_face_count(const std::string& path);

}  // namespace dlfl::bench

#pragma once
// The body of the OBJ, OFF and PLY harnesses: parse a file held in memory, build the mesh, and check what a
// successful read promises: the mesh validates, and it writes and reads back to the same polygons.

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/parsed_polygons.h>
#include <dlfl/polygon_soup.h>
#include <dlfl/validate.h>

#include "fuzz_common.h"

namespace dlfl::fuzz {

/// Inputs longer than this are skipped (run_fuzzers.sh passes the same -max_len).
inline constexpr std::size_t max_mesh_file = 64 * 1024;

using Parser = ParsedPolygons (*)(std::string_view text, const std::string& name);
using Writer = std::function<void(std::ostream&, const PolygonSoup&)>;

inline bool same_polygons(const PolygonSoup& a, const PolygonSoup& b) {
  return a.positions == b.positions && a.offsets == b.offsets && a.indices == b.indices;
}

/// Reads `text` with `parse`; on success checks the mesh and, for each writer, that writing its polygons and
/// reading them back gives the same polygons. Throws dlfl::Error for bad input only.
inline void check_polygon_file(std::string_view text, Parser parse, std::initializer_list<Writer> writers) {
  const Mesh mesh = build_mesh(parse(text, input_name), input_name);
  const ValidationReport report = validate(mesh, 1);
  if (!report.valid()) finding("the mesh read does not validate: " + report.violations.at(0).message);
  PolygonSoup soup;
  try {
    soup = to_polygons(mesh);
  } catch (const TopologyError&) {
    return;  // a 2-gon or a double edge, which no polygon file can hold: refusing to write it is right
  }
  for (const Writer& write : writers) {
    std::ostringstream out;
    write(out, soup);
    PolygonSoup again;
    try {
      again = to_polygons(build_mesh(parse(out.str(), "rewritten"), "rewritten"));
    } catch (const Error& e) {
      finding(std::string("what was read does not read back after writing: ") + e.what());
    }
    check(same_polygons(soup, again), "what was read reads back different after writing");
  }
}

/// The whole harness of a polygon format: inputs over the cap are skipped, and bad input (a dlfl::Error) is
/// what a reader may answer, not a finding.
inline int fuzz_polygon_file(const std::uint8_t* data, std::size_t size, Parser parse,
                             std::initializer_list<Writer> writers) {
  if (size > max_mesh_file) return 0;
  try {
    check_polygon_file(text_of(data, size), parse, writers);
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace dlfl::fuzz

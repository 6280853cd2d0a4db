// The native JSON mesh format (dlfl/io/json_mesh.h), as read_mesh reads a .json file: parse, build, validate,
// write and read back to an equal mesh.

#include <nlohmann/json.hpp>

#include <dlfl/errors.h>
#include <dlfl/io/json_mesh.h>
#include <dlfl/validate.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > 64 * 1024) return 0;
  const nlohmann::json doc = nlohmann::json::parse(fuzz::text_of(data, size), nullptr, false);
  if (doc.is_discarded()) return 0;  // read_mesh: IoError "not valid JSON"
  try {
    const Mesh mesh = mesh_from_json(doc, fuzz::input_name);
    const ValidationReport report = validate(mesh, 1);
    if (!report.valid()) fuzz::finding("the mesh read does not validate: " + report.violations.at(0).message);
    // write_mesh writes exactly this text.
    const std::string text = mesh_to_json(mesh).dump();
    const nlohmann::json again = nlohmann::json::parse(text, nullptr, false);
    fuzz::check(!again.is_discarded(), "the written mesh is not valid JSON");
    try {
      fuzz::check(mesh_from_json(again, "rewritten") == mesh, "the mesh reads back different after writing");
    } catch (const Error& e) {
      fuzz::finding(std::string("the written mesh does not read back: ") + e.what());
    }
  } catch (const Error&) {
  }
  return 0;
}

#pragma once
// What `dlfl edit` and `dlfl subdivide` share: an editor on the input file, and the result written with its
// operation log.

#include <string>

#include <dlfl/history/editor.h>

namespace dlfl::tool {

/// An editor holding the mesh of `in` as its first entry; its log embeds the meshes when `self_contained`.
Editor open_editor(const std::string& in, bool self_contained);

/// Writes the editor's mesh to `out` (binary PLY unless `ascii`) and, unless `log` is empty, its operation
/// log there: both or neither (a FileBatch), no temporary file left on failure.
void save_editor(const Editor& editor, const std::string& out, bool ascii, const std::string& log);

}  // namespace dlfl::tool

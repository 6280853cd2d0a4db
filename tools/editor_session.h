#pragma once
// What `dlfl edit` and `dlfl subdivide` share: their files (the input, the output and the operation log), an
// editor on the input file, and the result written with its log.

#include <CLI/CLI.hpp>
#include <string>

#include <dlfl/history/editor.h>

namespace dlfl::tool {

/// The files of a command that runs an editor on a mesh file, and how the outputs are written.
struct EditorFiles {
  std::string in, out, log;
  bool self_contained = false;
  bool ascii = false;
};

/// Declares `-o,--output` (required), `--log`, `--self-contained` and `--ascii` on `cmd`. The command
/// declares its input itself, with its own help.
void add_output_options(CLI::App* cmd, EditorFiles& files, const std::string& output_help,
                        const std::string& ascii_help);

/// Refuses a file named twice and an unwritable output or log before any work (file_checks.h).
void check_editor_files(const EditorFiles& files);

/// An editor holding the mesh of `files.in` as its first entry; its log embeds the meshes when
/// `files.self_contained`. With `keep_history` false it keeps nothing for undo (a command that never undoes
/// frees each replaced mesh at once).
Editor open_editor(const EditorFiles& files, bool keep_history);

/// Writes the editor's mesh to `files.out` (binary PLY unless `files.ascii`) and, unless `files.log` is
/// empty, its operation log there: both or neither (a FileBatch), no temporary file left on failure.
void save_editor(const Editor& editor, const EditorFiles& files);

}  // namespace dlfl::tool

#include "file_checks.h"

#include <filesystem>
#include <system_error>

#include <dlfl/io/atomic_file.h>

namespace fs = std::filesystem;

namespace dlfl::tool {

namespace {

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec) && !ec) return true;  // both exist: one inode (links, spellings, hard links)
  // One or both do not exist yet: compare what writing would create, through the links that do exist.
  const fs::path ra = fs::weakly_canonical(write_target(a), ec);
  if (ec) return false;
  const fs::path rb = fs::weakly_canonical(write_target(b), ec);
  return !ec && ra == rb;
}

}  // namespace

void check_files(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
  std::vector<const NamedFile*> all;
  for (const auto* list : {&inputs, &outputs})
    for (const NamedFile& f : *list)
      if (!f.path.empty()) all.push_back(&f);
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (!same_file(all[i]->path, all[j]->path)) continue;
      throw UsageError(all[i]->role + " " + all[i]->path + " and " + all[j]->role + " " + all[j]->path +
                       " are the same file; writing one would destroy the other");
    }
  }
  for (const NamedFile& f : outputs)
    if (!f.path.empty()) check_writable(f.path);
}

}  // namespace dlfl::tool

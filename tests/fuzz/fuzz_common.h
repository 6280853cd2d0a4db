#pragma once
// Shared by the libFuzzer harnesses (tests/fuzz/*.cpp, docs/fuzzing.md). Each harness defines
// LLVMFuzzerTestOneInput and follows one rule: a dlfl::Error is the right answer to bad input and is caught;
// anything else is a finding. Other exceptions are left to escape (libFuzzer, and the replay driver of the
// normal test run, then abort on them), and a broken invariant of a successful read (a mesh that does not
// validate, a file that does not read back as it was written) aborts with a message here.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/detail/block_cache.h>

namespace dlfl::fuzz {

#if defined(DLFL_FUZZ_HARNESS)
/// A libFuzzer build must see every allocation (tests/fuzz/CMakeLists.txt): at start-up, a block large
/// enough for the block cache is freed, and the cache must not have kept it.
inline const bool block_cache_is_off = [] {
  const std::size_t bytes = std::size_t(3) << 20;
  detail::release_block(detail::acquire_block(bytes), bytes);
  if (block_cache_size() != 0) {
    std::fputs("dlfl fuzz: the block cache is compiled in; build with -DDLFL_FUZZ=ON\n", stderr);
    std::abort();
  }
  return true;
}();
#endif

/// The name the readers put in their messages.
inline const std::string input_name = "fuzz-input";

/// The input as text.
inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// A broken invariant: print it and abort, which libFuzzer reports as a crash and saves the input.
[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "dlfl fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void check(bool ok, const std::string& what) {
  if (!ok) finding(what);
}

/// The input's lines, without their '\n' (and a '\r' before it); at most `max_lines` of them.
inline std::vector<std::string_view> lines_of(std::string_view text, std::size_t max_lines) {
  std::vector<std::string_view> out;
  while (!text.empty() && out.size() < max_lines) {
    const std::size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    out.push_back(line);
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
  return out;
}

/// The bundled cube (data/cube.obj) and tetrahedron (data/tetrahedron.off), as OBJ text: the small meshes
/// that the scheme and operation harnesses work on, so that no valid input can take long.
inline constexpr std::string_view cube_obj =
    "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
inline constexpr std::string_view tetrahedron_obj =
    "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";

}  // namespace dlfl::fuzz

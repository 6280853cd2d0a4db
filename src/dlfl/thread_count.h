#pragma once
// How many threads the library's parallel passes use (docs/performance.md, "Threads"). The geometry passes of
// the schemes and the parsers split their work into chunks whose bounds do not depend on the thread count,
// and no chunk's result depends on another's order, so every result is bit-identical whatever the count: mesh
// hashes and logs do not change with it.

namespace dlfl {

/// The number of threads the library's parallel passes may use: the last `set_thread_count`, else the
/// environment variable DLFL_THREADS when it holds a positive integer, else the number of cores. At least 1.
/// Thread-safe.
unsigned thread_count();

/// Sets the number of threads (1: every pass runs on the calling thread). 0 restores the default
/// (DLFL_THREADS or the number of cores). Takes effect for passes that start afterwards; passes already
/// running keep their threads. Thread-safe. Throws InvalidArgument above 1024.
void set_thread_count(unsigned count);

}  // namespace dlfl

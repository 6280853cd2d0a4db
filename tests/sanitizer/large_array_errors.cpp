// A deliberate memory error on a large element array (3 MiB, past the 2 MiB where the block cache took
// over): `overflow` reads one element past the end, `use-after-free` reads a freed array. CTest expects
// AddressSanitizer's report; with the block cache in the way (a block rounded up to 4 MiB, a freed block kept
// mapped) both reads would go unseen and the program would print "unseen" and exit 0.

#include <cstdio>
#include <string_view>

#include <dlfl/detail/large_allocator.h>

int main(int argc, char** argv) {
  const std::string_view what = argc == 2 ? argv[1] : "";
  const std::size_t n = (std::size_t(3) << 20) / sizeof(double);
  volatile double sink = 0;  // keeps the bad read from being optimised away
  if (what == "overflow") {
    dlfl::detail::LargeVector<double> a(n, 1.0);
    sink = a.data()[n];
  } else if (what == "use-after-free") {
    const double* p = nullptr;
    {
      dlfl::detail::LargeVector<double> a(n, 1.0);
      p = a.data();
    }
    sink = *p;
  } else {
    std::fputs("usage: large_array_errors overflow|use-after-free\n", stderr);
    return 2;
  }
  std::printf("unseen (read %g)\n", static_cast<double>(sink));
  return 0;
}

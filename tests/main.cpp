// Test runner: floating-point exceptions (invalid operation, division by zero, overflow)
// trap, so any NaN or infinity produced inside the library aborts the test that made it.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#if defined(__GLIBC__)
#include <fenv.h>
#endif

int main(int argc, char* argv[]) {
#if defined(__GLIBC__)
  feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
#endif
  return Catch::Session().run(argc, argv);
}

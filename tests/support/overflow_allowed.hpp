// Floating-point overflow allowed in a scope of a test (the runner traps it: tests/main.cpp).
#pragma once

#include <cstddef>  // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <fenv.h>
#endif

namespace sscc::test {

/// Overflow does not trap while this lives: for inputs whose bounds overflow by design (or a
/// library routine that overflows on the way, as Eigen's stableNorm on subnormal vectors), to
/// check what they return then.
struct OverflowAllowed {
#if defined(__GLIBC__)
  int trapped = fedisableexcept(FE_OVERFLOW);
  ~OverflowAllowed() {
    feclearexcept(FE_OVERFLOW);
    feenableexcept(trapped);
  }
#endif
};

}  // namespace sscc::test

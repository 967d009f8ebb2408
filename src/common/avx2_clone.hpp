// Runtime dispatch of a hot loop to AVX2, for builds that target baseline x86-64.
//
// A function marked SSCC_AVX2_CLONE is compiled twice, for baseline x86-64 and for AVX2, and
// the loader picks the clone the processor runs (glibc's ifunc). AVX2 is asked without FMA, so
// with the project's flags (baseline x86-64: no -march, -mfma or -ffast-math) the compiler never
// contracts a product and a sum: each clone does the same IEEE operations in the same order
// (vectorizing never reassociates without -ffast-math), and both return the same values bit
// for bit; only the width of the vector registers differs. Elsewhere the mark is empty: other
// architectures and C libraries; clang (clang 14 drops the attribute without a word on a
// function of a namespace declared first without it, as in a public header); and sanitizer
// builds, whose instrumented ifunc resolver could run before the sanitizer's runtime is set up.
#pragma once

#include <cstddef>  // defines __GLIBC__ on glibc

#if defined(__x86_64__) && defined(__GLIBC__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define SSCC_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define SSCC_AVX2_CLONE
#endif

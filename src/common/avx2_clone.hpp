// Runtime dispatch of a hot loop to AVX2, for builds that target baseline x86-64.
//
// A function marked SSCC_AVX2_CLONE is compiled twice, for baseline x86-64 and for AVX2, and
// the loader picks the clone the processor runs (GNU ifunc). AVX2 is asked without FMA, so the
// compiler never contracts a product and a sum: each clone does the same IEEE operations in the
// same order (vectorizing never reassociates without -ffast-math), and both return the same
// values bit for bit; only the width of the vector registers differs. Elsewhere the mark is
// empty: other architectures, and clang (clang 14 drops the attribute without a word on a
// function of a namespace declared first without it, as in a public header).
#pragma once

#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__)
#define SSCC_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define SSCC_AVX2_CLONE
#endif

// How many threads the library uses where an options struct leaves the count at 0 (the
// queries, scene steps and the certificates' precomputation).
#pragma once

namespace sscc {

/// The count set by set_default_threads when positive, otherwise every thread OpenMP may
/// use (the cores, or OMP_NUM_THREADS when set). Process-wide; read at the start of each call.
int default_threads();

/// Sets default_threads(); 0 returns to every core. Throws std::invalid_argument for a
/// negative count.
void set_default_threads(int threads);

}  // namespace sscc

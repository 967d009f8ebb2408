// Inputs and outputs of the continuous collision kernels (vertex-face and edge-edge).
#pragma once

#include <cstdint>

namespace sscc::ccd {

/// Default time-of-impact tolerance (in units of the step, t in [0, 1]). The reported time
/// of impact lies in [t* - tolerance, t*] for the true first contact t*. Smaller values cost
/// a few bisections more per hit (about 60 ns each) and change no contact decision.
inline constexpr double kDefaultToiTolerance = 1e-6;
/// Smallest accepted time-of-impact tolerance: bisection points stay exact dyadic doubles
/// (1 - t is exact) only down to this width; a smaller request is raised to it.
inline constexpr double kMinToiTolerance = 0x1p-48;
/// Relative width of the distance band in which the minimum-separation mode may report a
/// contact that is not one (a false positive): distance in (d, d (1 + this)]. Smaller values
/// cost more subdivision; zero could exhaust the box budget. It never causes a false
/// negative.
inline constexpr double kSeparationRelativeTolerance = 1e-3;
/// Upper bound on the subdivision boxes (time intervals) examined by the minimum-separation
/// mode. When it is reached the answer is "contact" at the earliest time not excluded
/// (conservative).
inline constexpr int kSeparationMaxBoxes = 1 << 16;

struct CcdOptions {
  /// Time-of-impact tolerance, see kDefaultToiTolerance.
  double toi_tolerance = kDefaultToiTolerance;
  /// Minimum separation d (same unit as the coordinates). 0: contact means touching, and
  /// the answer is exact. d > 0: contact means the distance falls to d at some t; the
  /// answer is conservative (never a false negative, false positives only for distances
  /// within d (1 + kSeparationRelativeTolerance)).
  double minimum_separation = 0.0;
};

/// Which stage of the kernel decided the answer (for statistics and tests).
enum class DecidedBy : std::uint8_t {
  kSweptBoxes,       ///< the axis-aligned boxes swept by the two primitives are disjoint (as
                     ///< given, or in the frame moving with their mean displacement)
  kCoplanaritySign,  ///< the coplanarity cubic has a certain sign on all of [0, 1]
  kIntervalFilter,   ///< root bracketing and inside tests with rounding-error bounds
  kExact,            ///< exact rational arithmetic (the filters could not decide)
  kSeparationSearch  ///< the minimum-separation subdivision search (d > 0)
};
inline constexpr int kDecidedByCount = 5;
const char* to_string(DecidedBy stage);

/// Output of a kernel. `toi` and `params` are meaningful only when `hit` is true.
struct CcdResult {
  bool hit = false;
  /// Time of impact in [0, 1], never later than the true first contact, within
  /// CcdOptions::toi_tolerance of it.
  double toi = 1.0;
  /// Contact parameters at `toi`, computed in floating point (approximate):
  /// vertex-face: barycentric weights of f1 and f2 (f0's is 1 - params[0] - params[1]);
  /// edge-edge: positions along edge a and along edge b, each in [0, 1].
  double params[2] = {0.0, 0.0};
  DecidedBy decided_by = DecidedBy::kSweptBoxes;
};

}  // namespace sscc::ccd

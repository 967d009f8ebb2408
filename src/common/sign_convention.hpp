// A sign convention for computed bases: eigen- and singular vectors are defined up to sign,
// and solvers pick either, so bases would differ from run to run (and machine to machine)
// without one.
#pragma once

#include <Eigen/Core>

namespace sscc {

/// Flips each column so that its largest-magnitude entry is positive.
inline void make_largest_entries_positive(Eigen::MatrixXd& vectors) {
  for (Eigen::Index c = 0; c < vectors.cols(); ++c) {
    Eigen::Index largest = 0;
    vectors.col(c).cwiseAbs().maxCoeff(&largest);
    if (vectors(largest, c) < 0.0) vectors.col(c) *= -1.0;
  }
}

}  // namespace sscc

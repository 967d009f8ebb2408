// Finiteness checks that do no arithmetic on the values (Eigen's allFinite computes x - x,
// which raises the invalid-operation exception for an infinity, trapped in the tests).
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace sscc {

template <typename Derived>
bool all_finite(const Eigen::DenseBase<Derived>& m) {
  for (Eigen::Index j = 0; j < m.cols(); ++j) {
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      if (!std::isfinite(m(i, j))) return false;
    }
  }
  return true;
}

}  // namespace sscc

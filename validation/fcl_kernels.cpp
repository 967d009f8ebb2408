#include "fcl_kernels.hpp"

#include <stdexcept>

#if SSCC_WITH_FCL
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>
#endif

namespace sscc::validation {

#if SSCC_WITH_FCL
bool fcl_available() { return true; }

bool run_fcl(const Query& q) {
  using Intersect = fcl::detail::Intersect<double>;
  const auto& p = q.points;
  double time = 0.0;
  fcl::Vector3<double> point;
  if (q.kind == Kind::kVertexFace) {
    return Intersect::intersect_VF(p[1], p[2], p[3], p[0], p[5], p[6], p[7], p[4], &time, &point);
  }
  return Intersect::intersect_EE(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], &time, &point);
}
#else
bool fcl_available() { return false; }

bool run_fcl(const Query&) { throw std::logic_error("sscc was built without FCL (SSCC_WITH_FCL=OFF)"); }
#endif

}  // namespace sscc::validation

// Links against an installed sscc and answers one query: a vertex falling through a
// triangle halfway through the step.
#include <sscc/sscc.hpp>

#include <cstdio>

int main() {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto r = sscc::ccd::vertex_face_ccd(Eigen::Vector3d(0.2, 0.2, 1), a, b, c,
                                            Eigen::Vector3d(0.2, 0.2, -1), a, b, c);
  std::printf("hit=%d toi=%.6f\n", r.hit, r.toi);
  return r.hit && r.toi <= 0.5 && r.toi > 0.49 ? 0 : 1;
}

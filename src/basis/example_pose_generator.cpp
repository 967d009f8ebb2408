#include "sscc/basis/example_pose_generator.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "sscc/model/polynomial_basis.hpp"

namespace sscc {

namespace {

void check_amplitude(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("example poses: the ") + name + " must be a non-negative finite number");
  }
}

}  // namespace

Eigen::MatrixXd generate_example_poses(const TriangleMesh& mesh, const ExamplePoseOptions& options) {
  if (options.poses < 1) throw std::invalid_argument("example poses: at least one pose must be asked for");
  check_amplitude(options.twist, "twist");
  check_amplitude(options.bend, "bend");
  check_amplitude(options.modal_amplitude, "modal amplitude");
  const Eigen::MatrixXd modes = polynomial_basis(mesh, options.modes);  // checks the count and the extent
  Eigen::Vector3d lo = mesh.vertices()[0];
  Eigen::Vector3d hi = lo;
  for (const Eigen::Vector3d& p : mesh.vertices()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  Eigen::Index longest = 0;
  Eigen::Index shortest = 0;
  const Eigen::Vector3d extent = hi - lo;
  extent.maxCoeff(&longest);
  extent.minCoeff(&shortest);
  if (shortest == longest) shortest = (longest + 1) % 3;  // a cube: any other axis
  const double half_length = 0.5 * extent[longest];       // > 0: polynomial_basis refused a point
  const Eigen::Vector3d long_axis = Eigen::Vector3d::Unit(longest);
  const Eigen::Vector3d short_axis = Eigen::Vector3d::Unit(shortest);

  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> normal;
  const double mode_scale = options.modal_amplitude / std::sqrt(static_cast<double>(options.modes));
  Eigen::MatrixXd poses(3L * mesh.vertex_count(), options.poses);
  for (int k = 0; k < options.poses; ++k) {
    const double tau = options.twist * unit(rng);
    const double beta = options.bend * unit(rng);
    Eigen::VectorXd amplitudes(options.modes);
    for (int i = 0; i < options.modes; ++i) amplitudes[i] = mode_scale * normal(rng);
    const Eigen::VectorXd displaced = modes * amplitudes;
    for (int v = 0; v < mesh.vertex_count(); ++v) {
      const Eigen::Vector3d& p = mesh.vertices()[v];
      const double s = (p[longest] - centre[longest]) / half_length;
      const Eigen::Matrix3d rotation =
          (Eigen::AngleAxisd(beta * s, short_axis) * Eigen::AngleAxisd(tau * s, long_axis)).toRotationMatrix();
      poses.col(k).segment<3>(3L * v) = centre + rotation * (p + displaced.segment<3>(3L * v) - centre);
    }
  }
  return poses;
}

}  // namespace sscc

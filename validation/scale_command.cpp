#include "scale_command.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "progress_bar.hpp"
#include "sscc/common/timing.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "stress/stress_inputs.hpp"
#include "trajectory.hpp"

namespace sscc::validation {

namespace {

/// The geodesic sphere of 20 f^2 triangles nearest N. Not the latitude-longitude sphere: its
/// slivers at the poles, and the long thin patches they make, cost the normal cones' radii
/// (SelfCcd::prepare) time growing as N^1.75 (2.3 s at 10^4 triangles, 246 s at 10^5), where
/// the geodesic sphere's grows as N^1.2, like real meshes'.
TriangleMesh sphere_of_about(long triangles) {
  return geodesic_sphere(std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 20.0)))));
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // kilobytes on Linux
}

}  // namespace

long run_scale(const ScaleOptions& o, std::ostream& out, std::ostream& progress) {
  if (o.steps < 1) throw std::invalid_argument("scale: at least one query step");
  const auto start = std::chrono::steady_clock::now();
  TriangleMesh mesh = o.mesh.empty() ? sphere_of_about(o.triangles) : read_mesh(o.mesh);
  progress << "scale: " << mesh.triangle_count() << " triangles, " << mesh.vertex_count() << " vertices\n";
  const Eigen::MatrixXd basis = polynomial_basis(mesh, o.modes);
  const SubspaceModel model(std::move(mesh), basis, Eigen::VectorXd::Ones(basis.cols()));

  auto t = std::chrono::steady_clock::now();
  const auto bvh = std::make_shared<const SubspaceBvh>(model);
  const double hierarchy_s = seconds_since(t);
  progress << "scale: hierarchy of " << bvh->nodes().size() << " nodes in " << hierarchy_s << " s\n";

  t = std::chrono::steady_clock::now();
  ProgressBar bar(progress, "scale: certificates");
  const auto certificates =
      std::make_shared<const Certificates>(Certificates::precompute(*bvh, {}, precompute_progress(bar)));
  bar.finish();
  const double certificates_s = seconds_since(t);

  t = std::chrono::steady_clock::now();
  const SelfCcd detector(bvh, certificates);
  const double detector_s = seconds_since(t);
  t = std::chrono::steady_clock::now();
  detector.prepare();  // what the first query would build
  const double prepare_s = seconds_since(t);

  const double radius = certificates->node_radius(0);
  const double amplitude = o.amplitude * (radius > 0.0 && std::isfinite(radius) ? radius : 1.0);
  const std::vector<Eigen::VectorXd> q = random_trajectory(model, o.steps, amplitude, o.seed);
  ProgressBar steps(progress, "scale: query steps");
  double query_s = 0.0;
  long colliding = 0;
  for (int k = 0; k < o.steps; ++k) {
    t = std::chrono::steady_clock::now();
    colliding += detector.query(q[k], q[k + 1]).collided();
    query_s += seconds_since(t);
    steps.update(k + 1, o.steps);
  }
  steps.finish("(" + std::to_string(colliding) + " colliding)");

  // Triangle pairs the precomputation screened one by one (its 1D bound or that bound's floor)
  // per pair of the mesh, N (N - 1) / 2: what the node pairs' box bounds left. A sibling pair's
  // descent and its pair certificates screen the same pairs, so up to about 2 when nothing is
  // culled.
  const PrecomputeStats& stats = certificates->stats();
  const double all_pairs = 0.5 * model.mesh().triangle_count() * (model.mesh().triangle_count() - 1.0);
  const long screened = stats.triangle_pairs_culled + stats.triangle_pairs_bounded;
  char line[512];
  std::snprintf(line, sizeof line,
                "scale: triangles=%d vertices=%d nodes=%zu hierarchy_s=%.3f certificates_s=%.3f detector_s=%.4f "
                "prepare_s=%.3f query_ms_per_step=%.3f colliding_steps=%ld total_s=%.3f peak_rss_mb=%.1f "
                "root_radius=%.6g pairs_screened=%ld screened_per_pair=%.3f",
                model.mesh().triangle_count(), model.mesh().vertex_count(), bvh->nodes().size(), hierarchy_s,
                certificates_s, detector_s, prepare_s, 1e3 * query_s / o.steps, colliding, seconds_since(start),
                peak_rss_mb(), radius, screened, all_pairs > 0.0 ? screened / all_pairs : 0.0);
  out << line << '\n';
  return 0;
}

}  // namespace sscc::validation

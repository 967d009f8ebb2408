#include "poses_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "progress_bar.hpp"
#include "sscc/experimental/cull_validation.hpp"
#include "sscc/experimental/node_collisions.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/query/pose_step_ccd.hpp"

namespace sscc::validation {

namespace {

using experimental::colliding_nodes;
using experimental::CullCounts;
using experimental::CullingPredictor;
using experimental::CullValidation;
using experimental::validate_culling;

/// The largest vertex residual over the poses (columns) for coordinates from `coordinates`.
template <typename Coordinates>
double largest_residual(const PoseSubspace& subspace, const Eigen::MatrixXd& poses, Coordinates coordinates) {
  double largest = 0.0;
  for (Eigen::Index p = 0; p < poses.cols(); ++p) {
    const Eigen::VectorXd pose = poses.col(p);
    largest = std::max(largest, subspace.residual(pose, coordinates(pose)).max_vertex);
  }
  return largest;
}

std::vector<Eigen::VectorXd> key_point_coordinates(const KeyPointMap& keys, const Eigen::MatrixXd& poses) {
  std::vector<Eigen::VectorXd> q;
  for (Eigen::Index p = 0; p < poses.cols(); ++p) q.push_back(keys.coordinates_of_pose(poses.col(p)));
  return q;
}

std::vector<std::vector<char>> ground_truth(const SubspaceBvh& bvh, const std::vector<Eigen::VectorXd>& q) {
  std::vector<std::vector<char>> truth;
  for (const Eigen::VectorXd& pose : q) truth.push_back(colliding_nodes(bvh, pose));
  return truth;
}

/// Steps from the mean shape to each pose (given positions) through the pose-step query:
/// how many fell back to the traditional query and how many collided.
struct PoseSteps {
  int steps = 0;
  int fell_back = 0;
  int collided = 0;
};

PoseSteps steps_from_mean(const PoseStepCcd& steps, const PoseSubspace& subspace,
                          const std::vector<Eigen::VectorXd>& poses) {
  PoseSteps result;
  for (const Eigen::VectorXd& pose : poses) {
    const PoseStepReport report = steps.query(subspace.mean_shape().vertices(), unstack_positions(pose));
    ++result.steps;
    result.fell_back += report.fell_back;
    result.collided += report.ccd.collided();
  }
  return result;
}

void print_counts(std::ostream& out, const char* label, const CullCounts& c) {
  char line[256];
  std::snprintf(line, sizeof line, "  %-52s culled=%ld false_culls=%ld poses_free=%d poses_falsely_free=%d", label,
                c.culled, c.false_culls, c.poses_declared_free, c.poses_falsely_free);
  out << line << '\n';
}

void print_validation(std::ostream& out, const char* which, const CullValidation& v) {
  char line[256];
  std::snprintf(line, sizeof line,
                "culling on %d %s poses x %d nodes (exact discrete test at the key-point coordinates: %ld "
                "colliding (pose, node) pairs, %d poses colliding):",
                v.poses, which, v.nodes, v.colliding, v.colliding_poses);
  out << line << '\n';
  print_counts(out, "sound certificates (||q||_M < R_n)", v.sound);
  print_counts(out, "EXPERIMENTAL regression predictor (NOT CONSERVATIVE)", v.predicted);
}

}  // namespace

long run_poses(const PosesCommandOptions& o, std::ostream& out, std::ostream& progress) {
  const auto start = std::chrono::steady_clock::now();
  MeshReadReport mesh_report;
  const TriangleMesh mesh = read_mesh(o.mesh, &mesh_report);
  const double diagonal = mesh.bounding_box_diagonal();
  progress << "mesh " << o.mesh << ": " << mesh.vertex_count() << " vertices, " << mesh.triangle_count()
           << " triangles (" << mesh_report.summary() << ")\n";

  ExamplePoseOptions generator = o.generator;
  generator.poses = o.training + o.held_out;
  const Eigen::MatrixXd poses = generate_example_poses(mesh, generator);
  const Eigen::MatrixXd training = poses.leftCols(o.training);
  const Eigen::MatrixXd held_out = poses.rightCols(o.held_out);
  progress << "poses: " << o.training << " training and " << o.held_out << " held-out poses generated\n";

  PcaOptions every_component;
  every_component.variance_fraction = 1.0;
  const PoseSubspace complete(mesh, training, every_component);
  const double training_residual =
      largest_residual(complete, training, [&](const Eigen::VectorXd& x) { return complete.project(x); });
  const PoseSubspace subspace(mesh, training, o.pca);
  progress << "pca: " << complete.mode_count() << " components, " << subspace.mode_count() << " kept\n";

  const KeyPointSelection selection = select_key_points(subspace, training, o.key_points);
  const KeyPointMap keys(subspace, selection.vertices);
  progress << "key points: " << selection.sampled << " sampled, " << selection.vertices.size() - selection.sampled
           << " added greedily\n";
  const double projection_residual =
      largest_residual(subspace, held_out, [&](const Eigen::VectorXd& x) { return subspace.project(x); });
  const double key_residual =
      largest_residual(subspace, held_out, [&](const Eigen::VectorXd& x) { return keys.coordinates_of_pose(x); });
  const std::vector<Eigen::VectorXd> training_q = key_point_coordinates(keys, training);
  const std::vector<Eigen::VectorXd> held_out_q = key_point_coordinates(keys, held_out);

  const SubspaceModel model = subspace.model();
  const SubspaceBvh bvh(model);
  progress << "bvh: " << bvh.build_stats().nodes << " nodes, depth " << bvh.build_stats().depth << '\n';
  ProgressBar bar(progress, "precompute");
  const Certificates certificates = Certificates::precompute(bvh, o.certificates, precompute_progress(bar));
  bar.finish();

  progress << "ground truth: exact discrete test of " << o.training + o.held_out << " poses\n" << std::flush;
  const std::vector<std::vector<char>> training_truth = ground_truth(bvh, training_q);
  const std::vector<std::vector<char>> held_out_truth = ground_truth(bvh, held_out_q);
  const CullingPredictor predictor = CullingPredictor::fit(bvh, training_q, training_truth);
  const CullValidation on_training = validate_culling(bvh, certificates, predictor, training_q, training_truth);
  const CullValidation on_held_out = validate_culling(bvh, certificates, predictor, held_out_q, held_out_truth);

  progress << "pose steps: from the mean shape to each held-out pose and to its key-point reconstruction\n";
  const PoseStepCcd steps(subspace, bvh, &certificates);
  std::vector<Eigen::VectorXd> given, reconstructed;
  for (Eigen::Index p = 0; p < held_out.cols(); ++p) {
    given.push_back(held_out.col(p));
    reconstructed.push_back(subspace.reconstruct(held_out_q[p]));
  }
  const PoseSteps to_given = steps_from_mean(steps, subspace, given);
  const PoseSteps to_reconstructed = steps_from_mean(steps, subspace, reconstructed);

  char line[512];
  std::snprintf(line, sizeof line, "poses: mesh=%s vertices=%d triangles=%d training=%d held_out=%d seed=%llu",
                o.mesh.c_str(), mesh.vertex_count(), mesh.triangle_count(), o.training, o.held_out,
                static_cast<unsigned long long>(generator.seed));
  out << line << '\n';
  std::snprintf(line, sizeof line, "pca: components=%d modes=%d explained_fraction=%.6f", complete.mode_count(),
                subspace.mode_count(), subspace.explained_fraction());
  out << line << '\n';
  std::snprintf(line, sizeof line,
                "reconstruction (largest vertex distance / box diagonal): training, all components %.3g; "
                "held-out, projection %.3g; held-out, from key points %.3g",
                training_residual / diagonal, projection_residual / diagonal, key_residual / diagonal);
  out << line << '\n';
  std::snprintf(line, sizeof line,
                "key points: %zu (%d sampled, %zu greedy) condition=%.3g training_rms_residual: sampled %.3g, "
                "final %.3g (box diagonals)",
                selection.vertices.size(), selection.sampled, selection.vertices.size() - selection.sampled,
                keys.condition_number(), selection.training_residual.front() / diagonal,
                selection.training_residual.back() / diagonal);
  out << line << '\n';
  std::snprintf(line, sizeof line, "certificates: nodes=%d root_radius=%.6g global_radius=%.6g precompute_s=%.3f",
                certificates.node_count(), certificates.node_radius(0), certificates.global_radius(),
                certificates.stats().seconds);
  out << line << '\n';
  std::snprintf(line, sizeof line,
                "pose steps from the mean shape (fallback when a vertex residual > %.3g box diagonals): to the "
                "held-out poses %d steps, %d fell back, %d collided; to their key-point reconstructions %d steps, "
                "%d fell back, %d collided",
                kSubspaceResidualFraction, to_given.steps, to_given.fell_back, to_given.collided,
                to_reconstructed.steps, to_reconstructed.fell_back, to_reconstructed.collided);
  out << line << '\n';
  print_validation(out, "training", on_training);
  print_validation(out, "held-out", on_held_out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::snprintf(line, sizeof line,
                "poses: sound_false_culls=%ld experimental_false_culls=%ld (EXPERIMENTAL, NOT CONSERVATIVE) "
                "time_s=%.3f",
                on_held_out.sound.false_culls + on_training.sound.false_culls, on_held_out.predicted.false_culls,
                seconds);
  out << line << '\n';
  return on_held_out.sound.false_culls + on_training.sound.false_culls;
}

}  // namespace sscc::validation

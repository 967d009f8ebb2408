#include "precompute_command.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "progress_bar.hpp"
#include "sscc/certificates/certificate_shards.hpp"

namespace sscc::validation {

void print_radius_per_level(const SubspaceBvh& bvh, const Certificates& certificates, std::ostream& out) {
  const std::vector<int> depth = bvh.node_depths();
  std::vector<std::vector<double>> radii(*std::max_element(depth.begin(), depth.end()) + 1);
  for (int n = 0; n < certificates.node_count(); ++n) radii[depth[n]].push_back(certificates.node_radius(n));
  for (std::size_t level = 0; level < radii.size(); ++level) {
    std::vector<double>& r = radii[level];
    std::sort(r.begin(), r.end());
    char line[200];
    std::snprintf(line, sizeof line, "level %zu: nodes=%zu min_radius=%.6g median_radius=%.6g max_radius=%.6g", level,
                  r.size(), r.front(), r[r.size() / 2], r.back());
    out << line << '\n';
  }
}

namespace {

/// The statistics, a warning when the root certifies nothing, the radius per level and the
/// summary line.
void report(const SubspaceBvh& bvh, const Certificates& certificates, bool exclude_rest_contacts, std::ostream& out,
            std::ostream& progress) {
  const PrecomputeStats& s = certificates.stats();
  progress << "precompute: " << s.threads << " threads, node pairs visited " << s.node_pairs_visited << " (culled "
           << s.node_pairs_culled << "), triangle pairs bounded " << s.triangle_pairs_bounded << " (culled by 1D "
           << s.triangle_pairs_culled << "), constant-mode evaluations " << s.constant_mode_evaluations
           << ", pair-tree tasks " << s.pair_tree_tasks << ", global radius " << certificates.global_radius() << '\n';
  if (certificates.node_radius(0) == 0.0) {
    progress << "precompute: warning: root radius 0: non-adjacent triangles touch or intersect at rest (or no "
                "motion is needed to bring them together); the root certifies nothing"
             << (exclude_rest_contacts ? "" : " (--exclude-rest-contacts ignores the pairs touching at rest)") << '\n';
  }
  print_radius_per_level(bvh, certificates, out);
  char line[256];
  std::snprintf(line, sizeof line, "precompute: triangles=%d nodes=%d r=%d time_s=%.3f root_radius=%.6g",
                bvh.model().mesh().triangle_count(), certificates.node_count(), bvh.model().mode_count(), s.seconds,
                certificates.node_radius(0));
  out << line << '\n';
}

}  // namespace

long run_precompute(const PrecomputeCommandOptions& o, std::ostream& out, std::ostream& progress) {
  const SubspaceModel model = load_model(o.model, progress);
  const SubspaceBvh bvh(model);
  progress << "bvh: " << bvh.build_stats().nodes << " nodes, depth " << bvh.build_stats().depth << '\n';
  if (o.shard_count > 0) {
    const std::string name = std::to_string(o.shard_index) + "/" + std::to_string(o.shard_count);
    ProgressBar bar(progress, "precompute shard " + name);
    const CertificateShard shard =
        Certificates::precompute_shard(bvh, o.parameters, o.shard_index, o.shard_count, precompute_progress(bar));
    bar.finish();
    shard.write(o.output);
    char line[256];
    std::snprintf(line, sizeof line, "precompute: shard=%s triangles=%d subtrees=%zu split_depth=%d time_s=%.3f",
                  name.c_str(), model.mesh().triangle_count(), shard.subtree_roots().size(), shard.split_depth(),
                  shard.stats().seconds);
    out << line << '\n';
    return 0;
  }
  ProgressBar bar(progress, "precompute");
  const Certificates certificates = Certificates::precompute(bvh, o.parameters, precompute_progress(bar));
  bar.finish();
  certificates.write(o.output);
  report(bvh, certificates, o.model.exclude_rest_contacts, out, progress);
  return 0;
}

long run_merge(const MergeCommandOptions& o, std::ostream& out, std::ostream& progress) {
  if (o.shards.empty()) throw std::invalid_argument("merge: no shard files given");
  const SubspaceModel model = load_model(o.model, progress);
  const SubspaceBvh bvh(model);
  progress << "bvh: " << bvh.build_stats().nodes << " nodes, depth " << bvh.build_stats().depth << '\n';
  std::vector<CertificateShard> shards;
  for (const std::string& path : o.shards) shards.push_back(CertificateShard::read(path, bvh));
  ProgressBar bar(progress, "merge");
  const Certificates certificates = Certificates::merge(bvh, shards, precompute_progress(bar));
  bar.finish();
  certificates.write(o.output);
  report(bvh, certificates, o.model.exclude_rest_contacts, out, progress);
  return 0;
}

}  // namespace sscc::validation

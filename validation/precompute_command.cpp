#include "precompute_command.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

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

long run_precompute(const PrecomputeCommandOptions& o, std::ostream& out, std::ostream& progress) {
  const SubspaceModel model = load_model(o.model, progress);
  const SubspaceBvh bvh(model);
  progress << "bvh: " << bvh.build_stats().nodes << " nodes, depth " << bvh.build_stats().depth << '\n';
  const Certificates certificates = Certificates::precompute(bvh, o.parameters, [&](int done, int levels) {
    progress << "precompute: level " << done << "/" << levels << " done\n" << std::flush;
  });
  certificates.write(o.output);
  const PrecomputeStats& s = certificates.stats();
  progress << "precompute: " << s.threads << " threads, node pairs visited " << s.node_pairs_visited << " (culled "
           << s.node_pairs_culled << "), triangle pairs bounded " << s.triangle_pairs_bounded << " (culled by 1D "
           << s.triangle_pairs_culled << "), constant-mode evaluations " << s.constant_mode_evaluations
           << ", global radius " << certificates.global_radius() << '\n';
  if (certificates.node_radius(0) == 0.0) {
    progress << "precompute: warning: root radius 0: non-adjacent triangles touch or intersect at rest (or no "
                "motion is needed to bring them together); the root certifies nothing"
             << (o.model.exclude_rest_contacts ? "" : " (--exclude-rest-contacts ignores the pairs touching at rest)")
             << '\n';
  }
  print_radius_per_level(bvh, certificates, out);
  char line[256];
  std::snprintf(line, sizeof line, "precompute: triangles=%d nodes=%d r=%d time_s=%.3f root_radius=%.6g",
                model.mesh().triangle_count(), certificates.node_count(), model.mode_count(), s.seconds,
                certificates.node_radius(0));
  out << line << '\n';
  return 0;
}

}  // namespace sscc::validation

#include "bench/self_ccd_table.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "fcl_self_ccd.hpp"
#include "model_loading.hpp"
#include "sscc/query/self_ccd.hpp"
#include "trajectory.hpp"

namespace sscc::validation {

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

std::vector<SelfCcdTableRow> self_ccd_table(const SelfCcdTableOptions& o, std::ostream& progress) {
  std::vector<SelfCcdTableRow> rows;
  for (const std::string& mesh : o.meshes) {
    const SubspaceModel model = load_model({mesh, o.basis, ""}, progress);
    const SubspaceBvh bvh(model);
    const SelfCcd ccd(bvh);
    SelfCcdOptions traditional, cones;
    traditional.use_certificates = cones.use_certificates = false;
    cones.use_normal_cones = true;
    FclSelfCcd fcl(model.mesh(), model.excluded_pairs());
    for (double amplitude : o.amplitudes) {
      progress << "self-CCD table: " << mesh << " amplitude " << amplitude << '\n';
      const std::vector<Eigen::VectorXd> q = random_trajectory(model, o.steps, amplitude, o.seed);
      SelfCcdTableRow row;
      row.mesh = std::filesystem::path(mesh).stem().string();
      row.triangles = model.mesh().triangle_count();
      row.amplitude = amplitude;
      for (int k = 0; k < o.steps; ++k) {
        // Alternate which runs first, so that neither always finds the caches warm.
        SelfCcdReport plain, culled;
        for (int order = 0; order < 2; ++order) {
          const bool plain_now = (order == 0) == (k % 2 == 0);
          const auto start = std::chrono::steady_clock::now();
          (plain_now ? plain : culled) = ccd.query(q[k], q[k + 1], plain_now ? traditional : cones);
          (plain_now ? row.traditional_ms : row.cones_ms) += milliseconds_since(start) / o.steps;
        }
        row.traditional_nodes += static_cast<double>(plain.stats.box_tests) / o.steps;
        row.cones_nodes += static_cast<double>(culled.stats.box_tests) / o.steps;
        row.traditional_pairs += static_cast<double>(plain.stats.triangle_pairs) / o.steps;
        row.cones_pairs += static_cast<double>(culled.stats.triangle_pairs) / o.steps;
        row.colliding_steps += plain.collided();
        row.identical = row.identical && plain.pairs == culled.pairs && plain.features == culled.features;
      }
      const int fcl_steps = std::min(o.fcl_steps, o.steps);
      for (int k = 0; k < fcl_steps; ++k) {
        const auto x0 = model.deformed_positions(q[k]);
        const auto x1 = model.deformed_positions(q[k + 1]);
        const auto start = std::chrono::steady_clock::now();
        fcl.step(x0, x1);
        row.fcl_ms += milliseconds_since(start) / fcl_steps;
      }
      rows.push_back(row);
    }
  }
  return rows;
}

std::string self_ccd_table_markdown(const std::vector<SelfCcdTableRow>& rows) {
  std::ostringstream md;
  md << "| mesh | triangles | amplitude | traditional | cones | FCL | cones vs traditional | FCL vs cones | "
        "node tests (trad / cones) | triangle pairs (trad / cones) | colliding | identical |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SelfCcdTableRow& r : rows) {
    md << "| " << r.mesh << " | " << r.triangles << " | " << r.amplitude << " | " << format("%.2f ms", r.traditional_ms)
       << " | " << format("%.2f ms", r.cones_ms) << " | " << format("%.1f ms", r.fcl_ms) << " | "
       << format("%.2fx", r.traditional_ms / r.cones_ms) << " | " << format("%.1fx", r.fcl_ms / r.cones_ms) << " | "
       << format("%.0f", r.traditional_nodes) << " / " << format("%.0f", r.cones_nodes) << " | "
       << format("%.0f", r.traditional_pairs) << " / " << format("%.0f", r.cones_pairs) << " | " << r.colliding_steps
       << " | " << (r.identical ? "yes" : "no") << " |\n";
  }
  return md.str();
}

}  // namespace sscc::validation

#include "bench/self_ccd_table.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "certificate_cache.hpp"
#include "fcl_self_ccd.hpp"
#include "model_loading.hpp"
#include "progress_bar.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/query/self_ccd.hpp"
#include "statistics.hpp"
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

/// The mesh's certificates from the cache, or computed and cached when absent or stale.
Certificates cached_certificates(const SubspaceBvh& bvh, const std::string& mesh, const SelfCcdTableOptions& o,
                                 std::ostream& progress) {
  std::string basis = o.basis;
  std::replace(basis.begin(), basis.end(), ':', '-');
  const std::filesystem::path file = std::filesystem::path(mesh).stem().string() + "-" + basis + ".sscc";
  return read_or_precompute_certificates(bvh, (std::filesystem::path(o.cache_dir) / file).string(), false,
                                         "self-CCD table", progress)
      .certificates;
}

}  // namespace

std::vector<SelfCcdTableRow> self_ccd_table(const SelfCcdTableOptions& o, std::ostream& progress) {
  std::vector<SelfCcdTableRow> rows;
  for (const std::string& mesh : o.meshes) {
    const SubspaceModel model = load_model({mesh, o.basis, ""}, progress);
    const SubspaceBvh bvh(model);
    const SelfCcd ccd(bvh, cached_certificates(bvh, mesh, o, progress));
    enum Method { kTraditional, kCones, kBounds, kBoth, kSscc, kMethods };
    std::array<SelfCcdOptions, kMethods> options;
    set_traditional(options[kTraditional]);
    set_traditional(options[kCones]);
    options[kCones].use_normal_cones = true;
    set_traditional(options[kBounds]);
    options[kBounds].use_displacement_bounds = true;
    options[kBoth].use_certificates = false;
    for (SelfCcdOptions& each : options) {
      each.threads = 1;
      ccd.prepare(each);  // precomputation, as the certificates: not timed
    }
    FclSelfCcd fcl(model.mesh(), model.excluded_pairs());
    ProgressBar bar(progress, "self-CCD table: " + std::filesystem::path(mesh).stem().string());
    const double table_steps = static_cast<double>(o.amplitudes.size()) * o.steps;
    long steps_done = 0;
    for (double amplitude : o.amplitudes) {
      const std::vector<Eigen::VectorXd> q = random_trajectory(model, o.steps, amplitude, o.seed);
      SelfCcdTableRow row;
      row.mesh = std::filesystem::path(mesh).stem().string();
      row.triangles = model.mesh().triangle_count();
      row.amplitude = amplitude;
      row.root_radius = ccd.certificates()->node_radius(0);
      const std::array<double*, kMethods> milliseconds{&row.traditional_ms, &row.cones_ms, &row.bounds_ms, &row.both_ms,
                                                       &row.sscc_ms};
      const std::array<double*, kMethods> nodes{&row.traditional_nodes, &row.cones_nodes, &row.bounds_nodes,
                                                &row.both_nodes, &row.sscc_nodes};
      for (int k = 0; k < o.steps; ++k) {
        // Each method's time on a step is the median of its repeats. A repeat runs every method
        // twice back to back and times the second run (warm caches, as FCL's steps run back
        // to back); the repeats interleave the methods, so that a drift of this machine's
        // speed weighs on all of them alike, and the order rotates with the step.
        std::array<SelfCcdReport, kMethods> reports;
        std::array<std::vector<double>, kMethods> repeats;
        for (int repeat = 0; repeat < std::max(1, o.repeats); ++repeat) {
          for (int i = 0; i < kMethods; ++i) {
            const int m = (i + k) % kMethods;
            ccd.query(q[k], q[k + 1], options[m]);
            const auto start = std::chrono::steady_clock::now();
            reports[m] = ccd.query(q[k], q[k + 1], options[m]);
            repeats[m].push_back(milliseconds_since(start));
          }
        }
        for (int m = 0; m < kMethods; ++m) {
          *milliseconds[m] += median(repeats[m]) / o.steps;
          *nodes[m] += static_cast<double>(reports[m].stats.box_tests) / o.steps;
        }
        row.traditional_pairs += static_cast<double>(reports[kTraditional].stats.triangle_pairs) / o.steps;
        row.cones_pairs += static_cast<double>(reports[kCones].stats.triangle_pairs) / o.steps;
        row.cones_plane_culled += static_cast<double>(reports[kCones].stats.plane_culled) / o.steps;
        row.root_certified_steps += reports[kSscc].stats.root_certified;
        row.colliding_steps += reports[kTraditional].collided();
        for (int m : {kCones, kBounds, kBoth, kSscc}) {
          row.identical = row.identical && reports[m].pairs == reports[kTraditional].pairs &&
                          reports[m].features == reports[kTraditional].features;
        }
        bar.update(static_cast<double>(++steps_done), table_steps, "amplitude " + format("%g", amplitude));
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
    bar.finish();
  }
  return rows;
}

std::string self_ccd_table_markdown(const std::vector<SelfCcdTableRow>& rows) {
  std::ostringstream md;
  md << "| mesh | triangles | amplitude | traditional | cones | bounds | cones + bounds | SSCC | FCL | "
        "cones vs traditional | SSCC vs cones | SSCC vs traditional | FCL vs cones | FCL vs cones + bounds | "
        "root-certified steps | node tests (trad / cones / bounds / cones + bounds / SSCC) | "
        "triangle pairs (trad / cones / cones' apart by their planes) | colliding | identical |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SelfCcdTableRow& r : rows) {
    md << "| " << r.mesh << " | " << r.triangles << " | " << r.amplitude << " | " << format("%.2f ms", r.traditional_ms)
       << " | " << format("%.2f ms", r.cones_ms) << " | " << format("%.2f ms", r.bounds_ms) << " | "
       << format("%.2f ms", r.both_ms) << " | " << format("%.4f ms", r.sscc_ms) << " | " << format("%.1f ms", r.fcl_ms)
       << " | " << format("%.2fx", r.traditional_ms / r.cones_ms) << " | " << format("%.2fx", r.cones_ms / r.sscc_ms)
       << " | " << format("%.2fx", r.traditional_ms / r.sscc_ms) << " | " << format("%.1fx", r.fcl_ms / r.cones_ms)
       << " | " << format("%.1fx", r.fcl_ms / r.both_ms) << " | " << r.root_certified_steps << " | "
       << format("%.0f", r.traditional_nodes) << " / " << format("%.0f", r.cones_nodes) << " / "
       << format("%.0f", r.bounds_nodes) << " / " << format("%.0f", r.both_nodes) << " / "
       << format("%.0f", r.sscc_nodes) << " | " << format("%.0f", r.traditional_pairs) << " / "
       << format("%.0f", r.cones_pairs) << " / " << format("%.0f", r.cones_plane_culled) << " | " << r.colliding_steps
       << " | " << (r.identical ? "yes" : "no") << " |\n";
  }
  return md.str();
}

}  // namespace sscc::validation

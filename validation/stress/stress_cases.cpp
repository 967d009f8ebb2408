#include "stress_cases.hpp"

#include <cmath>
#include <string>

#include "sscc/basis/modal_analysis.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "stress_inputs.hpp"

namespace sscc::validation {

namespace {

/// The small sphere most cases deform: 216 triangles, 110 vertices (bases up to rank 330),
/// about 23,000 non-adjacent pairs (350,000 kernel calls per brute-force step).
constexpr int kRings = 10;
constexpr int kSegments = 12;
/// Largest displacement of a random mode at unit coordinate, in sphere radii: a quarter of
/// the radius, so contacts need coordinates of order a few units.
constexpr double kModeSize = 0.25;
/// Gap between the parallel grids of the degenerate-mesh cases (grid size 1).
constexpr double kGridGap = 0.2;
constexpr int kGridCells = 6;
/// Certificates of the meshes of 5,000 triangles and more: radii resolved to half their
/// value (epsilon 0.5) and up to a tenth of the global radius, so that the precomputation
/// of a million triangles takes minutes, not hours.
const CertificateParameters kLargeMeshCertificates{0.5, 0.1};

/// The direction of the far translations: every coordinate large, none a power of two apart.
const Eigen::Vector3d kFarDirection(1.0, -0.75, 0.625);

std::string power_of_two(int exponent) { return "2^" + std::to_string(exponent); }

SubspaceModel unit_weights(TriangleMesh mesh, const Eigen::MatrixXd& basis) {
  const Eigen::VectorXd weights = Eigen::VectorXd::Ones(basis.cols());
  return SubspaceModel(std::move(mesh), basis, weights);
}

/// The sphere, scaled and moved, with a random basis of r modes scaled alike.
SubspaceModel random_sphere(int modes, double scale, const Eigen::Vector3d& offset, std::mt19937_64& rng) {
  TriangleMesh mesh = transformed(stress_sphere(kRings, kSegments), scale, offset);
  const Eigen::MatrixXd basis = random_basis(3 * mesh.vertex_count(), modes, kModeSize * scale, rng);
  return unit_weights(std::move(mesh), basis);
}

/// The triangles of the first regression far from the origin: a at height z, b one unit
/// above, one mode lowering b by one per unit coordinate (contact at ||q|| = 1).
SubspaceModel stacked_triangles(double z) {
  TriangleMesh mesh({{0, 0, z}, {10, 0, z}, {0, 10, z}, {1, 1, z + 1}, {8, 1, z + 1}, {1, 8, z + 1}},
                    {{0, 1, 2}, {3, 4, 5}});
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(18, 1);
  for (int v = 3; v < 6; ++v) basis(3 * v + 2, 0) = -1.0;
  return unit_weights(std::move(mesh), basis);
}

SubspaceModel random_model(TriangleMesh mesh, int modes, std::mt19937_64& rng) {
  const Eigen::MatrixXd basis = random_basis(3 * mesh.vertex_count(), modes, kGridGap, rng);
  return unit_weights(std::move(mesh), basis);
}

void add_translation_cases(std::vector<StressCase>& cases) {
  for (int exponent : {10, 20, 30, 40}) {
    cases.push_back({"translation", power_of_two(exponent) + " x size, polynomial r = 9",
                     [exponent](std::mt19937_64&) {
                       const double size = 2.0;  // the sphere's diameter
                       TriangleMesh mesh = transformed(stress_sphere(kRings, kSegments), 1.0,
                                                       std::ldexp(size, exponent) * kFarDirection);
                       return unit_weights(mesh, polynomial_basis(mesh, 9));
                     },
                     StressReference::kBruteForce, exponent == 40});
  }
  cases.push_back({"translation", "2^40 x size, random r = 30", [](std::mt19937_64& rng) {
                     return random_sphere(30, 1.0, std::ldexp(2.0, 40) * kFarDirection, rng);
                   }});
  for (double z : {0.0, 131072.0, std::ldexp(1.0, 40)}) {
    cases.push_back(
        {"translation", "stacked triangles at z = " + (z == 0 ? std::string("0") : power_of_two(int(std::log2(z)))),
         [z](std::mt19937_64&) { return stacked_triangles(z); }, StressReference::kBruteForce, z == 131072.0});
  }
}

void add_scale_cases(std::vector<StressCase>& cases) {
  for (int exponent : {-30, -10, 10, 30}) {
    cases.push_back({"scale", power_of_two(exponent) + ", random r = 12",
                     [exponent](std::mt19937_64& rng) {
                       return random_sphere(12, std::ldexp(1.0, exponent), Eigen::Vector3d::Zero(), rng);
                     },
                     StressReference::kBruteForce, exponent == -30});
  }
  cases.push_back({"scale", "2^-30 and 2^40 x size away, random r = 12", [](std::mt19937_64& rng) {
                     const double scale = std::ldexp(1.0, -30);
                     return random_sphere(12, scale, std::ldexp(2.0 * scale, 40) * kFarDirection, rng);
                   }});
  cases.push_back({"scale", "2^30 and 2^20 x size away, random r = 12", [](std::mt19937_64& rng) {
                     const double scale = std::ldexp(1.0, 30);
                     return random_sphere(12, scale, std::ldexp(2.0 * scale, 20) * kFarDirection, rng);
                   }});
}

void add_rank_cases(std::vector<StressCase>& cases) {
  for (int modes : {1, 2, 10, 50, 100, 300}) {
    cases.push_back({"rank", "random r = " + std::to_string(modes),
                     [modes](std::mt19937_64& rng) { return random_sphere(modes, 1.0, Eigen::Vector3d::Zero(), rng); },
                     StressReference::kBruteForce, modes == 2});
  }
}

void add_basis_cases(std::vector<StressCase>& cases) {
  cases.push_back({"basis", "modal r = 12 (TetGen, omega^2/2 weights)", [](std::mt19937_64&) {
                     const TriangleMesh mesh = stress_sphere(kRings, kSegments);
                     ElasticBasisOptions options;
                     options.modes = 12;
                     options.material.youngs_modulus = 1e5;
                     const ElasticBasis modal = modal_basis(mesh, options);
                     return SubspaceModel(mesh, modal.basis, modal.weights);
                   }});
  cases.push_back({"basis", "polynomial r = 27", [](std::mt19937_64&) {
                     const TriangleMesh mesh = stress_sphere(kRings, kSegments);
                     return unit_weights(mesh, polynomial_basis(mesh, 27));
                   }});
  for (double relative : {1e-9, 1e-15}) {
    cases.push_back(
        {"basis", "nearly rank 1, r = 10, columns differ by " + std::string(relative == 1e-9 ? "1e-9" : "1e-15"),
         [relative](std::mt19937_64& rng) {
           const TriangleMesh mesh = stress_sphere(kRings, kSegments);
           return unit_weights(mesh, nearly_dependent_basis(3 * mesh.vertex_count(), 10, kModeSize, relative, rng));
         },
         StressReference::kBruteForce, relative == 1e-15});
  }
  cases.push_back({"basis", "r = 10, columns scaled by 1e-8 and 1e8",
                   [](std::mt19937_64& rng) {
                     const TriangleMesh mesh = stress_sphere(kRings, kSegments);
                     Eigen::MatrixXd basis = random_basis(3 * mesh.vertex_count(), 10, kModeSize, rng);
                     for (int c = 0; c < basis.cols(); ++c) basis.col(c) *= c % 2 == 0 ? 1e-8 : 1e8;
                     return unit_weights(mesh, basis);
                   },
                   StressReference::kBruteForce, true});
  cases.push_back({"basis", "r = 13, weights 1e-6 to 1e6", [](std::mt19937_64& rng) {
                     const TriangleMesh mesh = stress_sphere(kRings, kSegments);
                     return SubspaceModel(mesh, random_basis(3 * mesh.vertex_count(), 13, kModeSize, rng),
                                          decade_weights(13, -6, 6));
                   }});
  cases.push_back(
      {"basis", "r = 13, weights 1e-6 to 1e6 against columns 1e-3 to 1e3, 2^30 away", [](std::mt19937_64& rng) {
         const TriangleMesh mesh =
             transformed(stress_sphere(kRings, kSegments), 1.0, std::ldexp(2.0, 30) * kFarDirection);
         Eigen::MatrixXd basis = random_basis(3 * mesh.vertex_count(), 13, kModeSize, rng);
         const Eigen::VectorXd columns = decade_weights(13, -3, 3);
         for (int c = 0; c < 13; ++c) basis.col(c) *= columns[c];
         return SubspaceModel(mesh, basis, decade_weights(13, -6, 6));
       }});
}

void add_degenerate_cases(std::vector<StressCase>& cases) {
  cases.push_back({"degenerate", "zero-area and sliver triangles, random r = 6", [](std::mt19937_64& rng) {
                     return random_model(degenerate_triangle_grids(kGridCells, kGridGap), 6, rng);
                   }});
  cases.push_back({"degenerate", "duplicated vertices (coincident grids), random r = 6", [](std::mt19937_64& rng) {
                     return random_model(duplicated_vertex_grids(kGridCells, kGridGap), 6, rng);
                   }});
  cases.push_back({"degenerate", "non-manifold edges (3 and 4 triangles), random r = 6",
                   [](std::mt19937_64& rng) { return random_model(non_manifold_grids(kGridCells, kGridGap), 6, rng); },
                   StressReference::kBruteForce, true});
  cases.push_back({"touching", "vertex on face at rest, random r = 3",
                   [](std::mt19937_64& rng) { return random_model(vertex_on_face_pair(), 3, rng); },
                   StressReference::kBruteForce, true});
  cases.push_back({"touching", "edge across edge at rest, random r = 3",
                   [](std::mt19937_64& rng) { return random_model(edge_on_edge_pair(), 3, rng); }});
}

void add_size_cases(std::vector<StressCase>& cases) {
  cases.push_back({"size", "1 triangle, random r = 3",
                   [](std::mt19937_64& rng) { return random_model(single_triangle(), 3, rng); },
                   StressReference::kBruteForce, true});
  // Latitude-longitude spheres of 5,000 (exhaustive reference), 10^5 and 10^6 triangles.
  // The million-triangle sphere gets the three linear modes that move x (stretch and shears):
  // its precomputation, in proportion to the mesh and r, must fit the run.
  struct Size {
    int rings, segments, modes;
    StressReference reference;
  };
  for (const Size size :
       {Size{26, 100, 9, StressReference::kExhaustive}, Size{201, 250, 9, StressReference::kTraditional},
        Size{501, 1000, 3, StressReference::kTraditional}}) {
    const int triangles = 2 * size.segments * (size.rings - 1);
    cases.push_back({"size", std::to_string(triangles) + " triangles, polynomial r = " + std::to_string(size.modes),
                     [size](std::mt19937_64&) {
                       const TriangleMesh mesh = stress_sphere(size.rings, size.segments);
                       return unit_weights(mesh, polynomial_basis(mesh, size.modes));
                     },
                     size.reference, false, kLargeMeshCertificates});
  }
}

}  // namespace

std::vector<StressCase> stress_cases() {
  std::vector<StressCase> cases;
  add_translation_cases(cases);
  add_scale_cases(cases);
  add_rank_cases(cases);
  add_basis_cases(cases);
  add_degenerate_cases(cases);
  add_size_cases(cases);
  return cases;
}

}  // namespace sscc::validation

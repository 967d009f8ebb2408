#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>

#include "sscc/model/basis_io.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/model/subspace_model.hpp"

namespace fs = std::filesystem;

namespace {

sscc::TriangleMesh tetrahedron() {
  return sscc::TriangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 3}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
}

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "sscc-test-model";
  fs::create_directories(dir);
  return (dir / name).string();
}

}  // namespace

TEST_CASE("deformation x = p + U q through the scaled basis", "[model]") {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  const sscc::TriangleMesh mesh = tetrahedron();
  Eigen::MatrixXd u(12, 4);
  for (long i = 0; i < u.size(); ++i) u.data()[i] = normal(rng);
  const Eigen::Vector4d weights(1.0, 4.0, 0.25, 9.0);
  const sscc::SubspaceModel model(mesh, u, weights);
  const Eigen::Vector4d q(0.3, -1.2, 2.0, 0.5);
  const std::vector<Eigen::Vector3d> x = model.deformed_positions(q);
  const Eigen::VectorXd displacement = u * q;
  for (int v = 0; v < 4; ++v) {
    CHECK((x[v] - mesh.vertices()[v] - displacement.segment<3>(3 * v)).norm() < 1e-12);
  }
  CHECK(model.weighted_norm(q) == Approx(std::sqrt((weights.array() * q.array().square()).sum())));
  CHECK((model.scaled_basis() * model.scaled_coordinates(q) - displacement).norm() < 1e-12);
}

TEST_CASE("both ends of a step are computed exactly as each end alone", "[model]") {
  // The queries compute a step's two ends in one pass; validation and the discrete queries
  // one at a time: reports agree only if the doubles do.
  std::mt19937_64 rng(23);
  std::normal_distribution<double> normal;
  const sscc::TriangleMesh mesh = tetrahedron();
  for (int r : {1, 3, 27, 64}) {
    Eigen::MatrixXd u(12, r);
    for (long i = 0; i < u.size(); ++i) u.data()[i] = normal(rng) * std::ldexp(1.0, static_cast<int>(i % 40) - 20);
    const sscc::SubspaceModel model(mesh, u, Eigen::VectorXd::Ones(r));
    Eigen::VectorXd q0(r), q1(r);
    for (int k = 0; k < r; ++k) q0[k] = normal(rng), q1[k] = normal(rng) * 1e-3;
    for (int v = 0; v < 4; ++v) {
      Eigen::Vector3d x0, x1;
      model.position_pair(v, q0, q1, x0, x1);
      CHECK(x0 == model.position(v, q0));
      CHECK(x1 == model.position(v, q1));
      CHECK((x0 - mesh.vertices()[v] - model.scaled_basis().middleRows<3>(3 * v) * q0).norm() <
            1e-9 * (1.0 + x0.norm()));
    }
  }
}

TEST_CASE("bad bases, weights and coordinates are refused with a message", "[model]") {
  const sscc::TriangleMesh mesh = tetrahedron();
  CHECK_THROWS_WITH(sscc::SubspaceModel(mesh, Eigen::MatrixXd::Ones(9, 2), Eigen::Vector2d(1, 1)),
                    Catch::Contains("9 rows") && Catch::Contains("need 12"));
  CHECK_THROWS_WITH(sscc::SubspaceModel(mesh, Eigen::MatrixXd::Ones(12, 2), Eigen::Vector3d(1, 1, 1)),
                    Catch::Contains("3 weights for 2 modes"));
  CHECK_THROWS_WITH(sscc::SubspaceModel(mesh, Eigen::MatrixXd::Ones(12, 2), Eigen::Vector2d(1, 0)),
                    Catch::Contains("weight 1"));
  Eigen::MatrixXd nan_basis = Eigen::MatrixXd::Ones(12, 2);
  nan_basis(3, 1) = std::nan("");
  CHECK_THROWS_WITH(sscc::SubspaceModel(mesh, nan_basis, Eigen::Vector2d(1, 1)), Catch::Contains("NaN"));
  const sscc::SubspaceModel model(mesh, Eigen::MatrixXd::Ones(12, 2), Eigen::Vector2d(1, 1));
  CHECK_THROWS_WITH(model.scaled_coordinates(Eigen::Vector3d(1, 2, 3)),
                    Catch::Contains("q has 3 coordinates") && Catch::Contains("2 modes"));
  CHECK_THROWS_WITH(model.scaled_coordinates(Eigen::Vector2d(1, std::nan(""))), Catch::Contains("q[1] is not finite"));
}

TEST_CASE("Vega .U files and text matrices round-trip; bad files are refused", "[model]") {
  std::mt19937_64 rng(6);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd u(12, 5);
  for (long i = 0; i < u.size(); ++i) u.data()[i] = normal(rng);
  const std::string path = scratch("basis.U");
  sscc::write_vega_basis(path, u);
  CHECK(fs::file_size(path) == 8u + 8u * 60u);
  CHECK(sscc::read_basis(path) == u);
  // Column-major: the first doubles after the header are column 0.
  std::ifstream in(path, std::ios::binary);
  std::int32_t header[2];
  double first[2];
  in.read(reinterpret_cast<char*>(header), 8);
  in.read(reinterpret_cast<char*>(first), 16);
  CHECK(header[0] == 12);
  CHECK(header[1] == 5);
  CHECK(first[0] == u(0, 0));
  CHECK(first[1] == u(1, 0));

  fs::resize_file(path, fs::file_size(path) - 8);
  CHECK_THROWS_WITH(sscc::read_vega_basis(path), Catch::Contains("does not match"));
  std::ofstream(scratch("text.U")) << "not a basis at all";
  CHECK_THROWS_WITH(sscc::read_vega_basis(scratch("text.U")), Catch::Contains("does not match"));
  std::ofstream(scratch("negative.U"), std::ios::binary) << std::string("\xff\xff\xff\xff\x01\0\0\0", 8);
  CHECK_THROWS_WITH(sscc::read_vega_basis(scratch("negative.U")), Catch::Contains("not a .U basis"));

  std::ofstream(scratch("m.txt")) << "# a matrix\n1 2 3\n4 5 6 # trailing comment\n\n";
  const Eigen::MatrixXd m = sscc::read_basis(scratch("m.txt"));
  CHECK(m.rows() == 2);
  CHECK(m(1, 2) == 6);
  std::ofstream(scratch("ragged.txt")) << "1 2 3\n4 5\n";
  CHECK_THROWS_WITH(sscc::read_text_matrix(scratch("ragged.txt")), Catch::Contains("line 2 has 2 numbers"));
  std::ofstream(scratch("inf.txt")) << "1 inf\n";
  CHECK_THROWS_WITH(sscc::read_text_matrix(scratch("inf.txt")), Catch::Contains("NaN or infinity"));
  const Eigen::Vector3d w(0.5, 2.0, 1e-3);
  sscc::write_weights(scratch("w.txt"), w);
  CHECK(sscc::read_weights(scratch("w.txt")) == w);
}

TEST_CASE("polynomial modes: linear then quadratic, scaled to the bounding-box diagonal", "[model]") {
  const sscc::TriangleMesh mesh = tetrahedron();
  const Eigen::MatrixXd u = sscc::polynomial_basis(mesh, 27);
  REQUIRE(u.cols() == 27);
  const double diagonal = mesh.bounding_box_diagonal();
  for (int m = 0; m < 27; ++m) {
    double largest = 0.0;
    for (int v = 0; v < 4; ++v) largest = std::max(largest, u.col(m).segment<3>(3 * v).norm());
    CHECK(largest == Approx(diagonal));
    // Each mode moves one axis only.
    int axes_moved = 0;
    for (int axis = 0; axis < 3; ++axis) {
      bool moves = false;
      for (int v = 0; v < 4; ++v) moves = moves || u(3 * v + axis, m) != 0.0;
      axes_moved += moves;
    }
    CHECK(axes_moved == 1);
  }
  // Mode 1 (x moved by y) is linear in y: its values are an affine function of rest y.
  const double a = u(3 * 0 + 0, 1);     // y = 0
  const double b = u(3 * 2 + 0, 1);     // y = 1
  CHECK(u(3 * 1 + 0, 1) == Approx(a));  // vertex 1 also has y = 0
  CHECK(b != Approx(a));
  CHECK_THROWS_WITH(sscc::polynomial_basis(mesh, 28), Catch::Contains("1 to 27"));
  CHECK(sscc::polynomial_basis(mesh, 9).cols() == 9);
}

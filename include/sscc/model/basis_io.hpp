// Reading and writing bases and weights.
//
// Vega FEM's binary .U layout: int rows, int cols (native 4-byte ints), then rows * cols
// doubles in column-major order, native byte order. Plain text matrices: one row per line,
// numbers separated by white space, '#' comments. Weights: r numbers in a text file.
// Errors (std::runtime_error) name the file and the problem: a truncated or oversized file,
// non-positive sizes, a NaN or infinity, rows of different lengths.
#pragma once

#include <Eigen/Core>

#include <string>

namespace sscc {

Eigen::MatrixXd read_vega_basis(const std::string& path);
void write_vega_basis(const std::string& path, const Eigen::MatrixXd& basis);
Eigen::MatrixXd read_text_matrix(const std::string& path);
Eigen::VectorXd read_weights(const std::string& path);
void write_weights(const std::string& path, const Eigen::VectorXd& weights);
/// By extension: ".U" (any case) is Vega binary, anything else a text matrix.
Eigen::MatrixXd read_basis(const std::string& path);

}  // namespace sscc

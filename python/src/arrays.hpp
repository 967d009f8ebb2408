// Conversions between NumPy arrays and the library's types.
//
// Inputs are read where they lie (any strides, any float dtype cast once when it is not
// float64) and copied only into the containers the C++ API takes. Outputs that live in a C++
// object owned by Python (a mesh's vertices, a report's pairs) are read-only views into it
// that keep their owner alive; results built for the caller are handed over without a copy.
// Bad shapes raise ValueError naming the argument and the shape received.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace sscc::python {

namespace py = pybind11;

/// A float64 array in C order: a copy is made only when the input is not one already.
using CArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// "(5, 2)".
std::string shape_text(const py::array& array);

/// A 1-D float array as a vector.
Eigen::VectorXd vector_from(py::handle object, const char* name);
/// A 2-D float array as a matrix.
Eigen::MatrixXd matrix_from(py::handle object, const char* name);
/// A length-3 float array as a point.
Eigen::Vector3d point_from(py::handle object, const char* name);
/// An (n, 3) float array as points.
std::vector<Eigen::Vector3d> points_from(py::handle object, const char* name);
/// An (n, 3) integer array as index triples (each fitting an int).
std::vector<std::array<int, 3>> index_triples_from(py::handle object, const char* name);

/// A read-only view of memory owned by `owner` (kept alive by the view). Shape and strides
/// (in bytes) as NumPy has them.
template <typename T>
py::array view(const T* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides, py::handle owner) {
  // With no data (an empty container) NumPy allocates the (empty) array and owns it.
  py::array result(py::dtype::of<T>(), std::move(shape), std::move(strides), data, owner);
  result.attr("flags").attr("writeable") = false;
  return result;
}

/// A read-only (rows, columns) view of a vector of fixed-size rows (Eigen vectors,
/// std::arrays) owned by `owner`.
template <typename Row>
py::array rows_view(const std::vector<Row>& rows, py::handle owner) {
  using Scalar = std::remove_const_t<std::remove_pointer_t<decltype(std::declval<const Row&>().data())>>;
  constexpr py::ssize_t columns = sizeof(Row) / sizeof(Scalar);
  static_assert(sizeof(Row) == columns * sizeof(Scalar), "rows are viewed as packed scalars");
  return view(rows.empty() ? nullptr : rows.front().data(), {py::ssize_t(rows.size()), columns},
              {py::ssize_t(sizeof(Row)), py::ssize_t(sizeof(Scalar))}, owner);
}

/// Hands a container over to NumPy without copying its elements (the array owns it).
template <typename T, typename Container>
py::array adopt(Container&& container, std::vector<py::ssize_t> shape) {
  auto* owned = new Container(std::forward<Container>(container));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<Container*>(p); });
  return py::array(py::dtype::of<T>(), std::move(shape), std::vector<py::ssize_t>{},
                   reinterpret_cast<const T*>(owned->data()), free_when_done);
}

}  // namespace sscc::python

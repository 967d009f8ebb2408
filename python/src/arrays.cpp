#include "arrays.hpp"

#include <limits>

namespace sscc::python {

namespace {

/// The object as a float64 array of any layout (cast once when it is another dtype).
py::array_t<double> float_array(py::handle object, const char* name) {
  auto array = py::array_t<double>::ensure(object);
  if (!array) throw py::value_error(std::string(name) + ": expected an array of numbers");
  return array;
}

[[noreturn]] void wrong_shape(const char* name, const char* wanted, const py::array& array) {
  throw py::value_error(std::string(name) + ": expected " + wanted + ", got shape " + shape_text(array));
}

/// Strides in elements (NumPy's are in bytes, always multiples of 8 for float64 arrays that
/// NumPy made; an unaligned view is copied first).
py::ssize_t element_stride(const py::array& array, int axis) { return array.strides(axis) / array.itemsize(); }

py::array_t<double> aligned(py::array_t<double> array) {
  for (int axis = 0; axis < array.ndim(); ++axis) {
    if (array.strides(axis) % array.itemsize() != 0) return py::array_t<double, py::array::c_style>::ensure(array);
  }
  return array;
}

}  // namespace

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (int axis = 0; axis < array.ndim(); ++axis) {
    if (axis > 0) text += ", ";
    text += std::to_string(array.shape(axis));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

Eigen::VectorXd vector_from(py::handle object, const char* name) {
  const auto array = aligned(float_array(object, name));
  if (array.ndim() != 1) wrong_shape(name, "a 1-D array", array);
  using Strided = Eigen::Map<const Eigen::VectorXd, Eigen::Unaligned, Eigen::InnerStride<Eigen::Dynamic>>;
  return Strided(array.data(), array.shape(0), Eigen::InnerStride<Eigen::Dynamic>(element_stride(array, 0)));
}

Eigen::MatrixXd matrix_from(py::handle object, const char* name) {
  const auto array = aligned(float_array(object, name));
  if (array.ndim() != 2) wrong_shape(name, "a 2-D array", array);
  using Stride = Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>;
  using Strided = Eigen::Map<const Eigen::MatrixXd, Eigen::Unaligned, Stride>;
  return Strided(array.data(), array.shape(0), array.shape(1),
                 Stride(element_stride(array, 1), element_stride(array, 0)));
}

Eigen::Vector3d point_from(py::handle object, const char* name) {
  const auto array = float_array(object, name);
  if (array.ndim() != 1 || array.shape(0) != 3) wrong_shape(name, "3 coordinates", array);
  return {array.at(0), array.at(1), array.at(2)};
}

std::vector<Eigen::Vector3d> points_from(py::handle object, const char* name) {
  const auto array = float_array(object, name);
  if (array.ndim() != 2 || array.shape(1) != 3) wrong_shape(name, "an (n, 3) array", array);
  const auto a = array.unchecked<2>();
  std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(array.shape(0)));
  for (py::ssize_t i = 0; i < array.shape(0); ++i) points[i] = {a(i, 0), a(i, 1), a(i, 2)};
  return points;
}

std::vector<std::array<int, 3>> index_triples_from(py::handle object, const char* name) {
  const auto any = py::array::ensure(object);
  // Casting floats to indices would truncate silently: only integers are accepted.
  if (!any || (any.dtype().kind() != 'i' && any.dtype().kind() != 'u')) {
    throw py::value_error(std::string(name) + ": expected an array of integers");
  }
  const auto array = py::array_t<long long, py::array::forcecast>::ensure(any);
  if (array.ndim() != 2 || array.shape(1) != 3) wrong_shape(name, "an (m, 3) array", array);
  const auto a = array.unchecked<2>();
  std::vector<std::array<int, 3>> triples(static_cast<std::size_t>(array.shape(0)));
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    for (int k = 0; k < 3; ++k) {
      const long long index = a(i, k);
      if (index < std::numeric_limits<int>::min() || index > std::numeric_limits<int>::max()) {
        throw py::value_error(std::string(name) + ": index " + std::to_string(index) + " in row " + std::to_string(i) +
                              " does not fit a 32-bit int");
      }
      triples[i][k] = static_cast<int>(index);
    }
  }
  return triples;
}

}  // namespace sscc::python

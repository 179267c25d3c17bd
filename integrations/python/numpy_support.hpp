#pragma once
// numpy ↔ C++ for the ellc module: validated 1-D float64 inputs (clear ValueError otherwise) and
// freshly allocated outputs whose buffers can be filled with the GIL released.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <string>

namespace ellc::python {

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style>;

// `value` as a contiguous 1-D float64 array. Lists and integer/float arrays are converted; any
// other dtype (bool, complex, str, object) or any other number of dimensions raises ValueError
// naming the argument.
DoubleArray vector_argument(const py::handle& value, const char* name);

// Same, and the length must equal `size` (another argument's).
DoubleArray vector_argument(const py::handle& value, const char* name, py::ssize_t size, const char* other);

inline std::span<const double> view(const DoubleArray& array) {
  return {array.data(), static_cast<std::size_t>(array.size())};
}

template <typename T>
py::array_t<T> new_vector(py::ssize_t size) {
  return py::array_t<T>(size);
}

}  // namespace ellc::python

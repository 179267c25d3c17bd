#include "numpy_support.hpp"

#include <sstream>

namespace ellc::python {

namespace {
std::string describe_shape(const py::array& array) {
  std::ostringstream out;
  out << '(';
  for (py::ssize_t axis = 0; axis < array.ndim(); ++axis) out << (axis ? ", " : "") << array.shape(axis);
  out << (array.ndim() == 1 ? ",)" : ")");
  return out.str();
}
}  // namespace

DoubleArray vector_argument(const py::handle& value, const char* name) {
  py::array array = py::array::ensure(value);
  if (!array)
    throw py::value_error(std::string(name) + ": expected a 1-D array of float64, got " +
                          std::string(py::str(py::type::of(value).attr("__name__"))));
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error(std::string(name) + ": expected a real numeric dtype (float64), got dtype('" +
                          std::string(py::str(array.dtype())) + "')");
  if (array.ndim() != 1)
    throw py::value_error(std::string(name) + ": expected a 1-D array, got shape " + describe_shape(array));
  return DoubleArray::ensure(array.attr("astype")("float64", py::arg("copy") = false));
}

DoubleArray vector_argument(const py::handle& value, const char* name, py::ssize_t size, const char* other) {
  DoubleArray array = vector_argument(value, name);
  if (array.size() != size)
    throw py::value_error(std::string(name) + ": expected the same length as " + other + " (" + std::to_string(size) +
                          "), got " + std::to_string(array.size()));
  return array;
}

}  // namespace ellc::python

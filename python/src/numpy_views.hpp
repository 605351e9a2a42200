// python/src/numpy_views.hpp: NumPy arrays over memory that C++ objects own, without copies;
// the points' view of a NumPy array.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "drange/points.hpp"

namespace drange::python {

namespace py = pybind11;

// Points as the engine reads them: float64, C order (NumPy converts anything else).
using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

inline PointsView points_view(const Points& points, const char* what) {
  if (points.ndim() != 2)
    throw py::value_error(std::string(what) + " must be a 2-D array of shape (npoints, ndim); got " +
                          std::to_string(points.ndim()) + " dimensions");
  return PointsView(points.data(), static_cast<std::size_t>(points.shape(0)), static_cast<int>(points.shape(1)));
}

// A row-major array over `data`, kept alive by `owner` (the Python object that owns the memory).
template <class T>
py::array_t<T> view(const std::vector<T>& data, std::vector<py::ssize_t> shape, py::handle owner) {
  return py::array_t<T>(std::move(shape), data.data(), owner);
}

// A rows x width array over `data` (data.size() = rows * width).
template <class T>
py::array_t<T> table_view(const std::vector<T>& data, std::size_t width, py::handle owner) {
  const auto rows = static_cast<py::ssize_t>(width ? data.size() / width : 0);
  return view(data, {rows, static_cast<py::ssize_t>(width)}, owner);
}

// Moves a vector into a NumPy array that owns it (freed with the array).
template <class T>
py::array_t<T> adopt(std::vector<T>&& data, std::vector<py::ssize_t> shape) {
  auto* heap = new std::vector<T>(std::move(data));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(std::move(shape), heap->data(), owner);
}

}  // namespace drange::python

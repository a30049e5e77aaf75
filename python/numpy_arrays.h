// Numpy arrays to and from the C++ containers of the data layer, for the Python module: points
// in file coordinates (the frame's origin added back), index and id arrays as int64. Arrays
// from Python are checked (shape, integer dtype, finite values, ids that fit an int) and refused
// with a ParameterError naming what was wrong.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/types.h"

namespace py = pybind11;

namespace voroseal::python {

// ---- to Python ---------------------------------------------------------------------------

inline py::array_t<double> points_array(const std::vector<Vec3>& points, const Vec3& origin) {
  py::array_t<double> array({static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(3)});
  auto a = array.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) a(i, k) = points[i][k] + origin[k];
  return array;
}

template <size_t N>
py::array_t<int64_t> index_array(const std::vector<std::array<int, N>>& items) {
  py::array_t<int64_t> array({static_cast<py::ssize_t>(items.size()), static_cast<py::ssize_t>(N)});
  auto a = array.mutable_unchecked<2>();
  for (size_t i = 0; i < items.size(); ++i)
    for (size_t k = 0; k < N; ++k) a(i, k) = items[i][k];
  return array;
}

inline py::array_t<int64_t> int_array(const std::vector<int>& items) {
  py::array_t<int64_t> array(static_cast<py::ssize_t>(items.size()));
  auto a = array.mutable_unchecked<1>();
  for (size_t i = 0; i < items.size(); ++i) a(i) = items[i];
  return array;
}

// ---- from Python -------------------------------------------------------------------------

inline py::array as_numpy(const py::handle& value) {
  return py::module_::import("numpy").attr("asarray")(value);
}

inline std::string shape_of(const py::array& a) {
  return py::str(a.attr("shape")).cast<std::string>();
}

// An integer array of shape (n, columns), or (n,) when columns is 0; an empty sequence is an
// empty array whatever its dtype. Floats are refused: truncating them would hide a mistake.
inline py::array_t<int64_t> integer_array(const py::handle& value, const std::string& what,
                                          int columns) {
  const py::array a = as_numpy(value);
  if (a.size() == 0)
    return columns > 0 ? py::array_t<int64_t>(std::vector<py::ssize_t>{0, columns})
                       : py::array_t<int64_t>(0);
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw ParameterError(what + " must hold integers, not " +
                         py::str(a.dtype()).cast<std::string>());
  if (columns > 0 && (a.ndim() != 2 || a.shape(1) != columns))
    throw ParameterError(what + " must be an (n, " + std::to_string(columns) + ") array, not " +
                         shape_of(a));
  if (columns == 0 && a.ndim() != 1)
    throw ParameterError(what + " must be a 1-d array, not " + shape_of(a));
  return a.cast<py::array_t<int64_t, py::array::c_style | py::array::forcecast>>();
}

inline int narrow(int64_t value, const std::string& what) {
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    throw ParameterError(what + " holds " + std::to_string(value) + ", out of range");
  return static_cast<int>(value);
}

template <size_t N>
std::vector<std::array<int, N>> fixed_cells(const int64_t* nodes, size_t count,
                                            const std::string& what) {
  std::vector<std::array<int, N>> cells(count);
  for (size_t i = 0; i < count; ++i)
    for (size_t k = 0; k < N; ++k) cells[i][k] = narrow(nodes[N * i + k], what);
  return cells;
}

template <size_t N>
std::vector<std::array<int, N>> cells_from(const py::handle& value, const std::string& what) {
  const py::array_t<int64_t> a = integer_array(value, what, N);
  return fixed_cells<N>(a.data(), static_cast<size_t>(a.shape(0)), what);
}

// Ids from Python; None: `count` zeros.
inline std::vector<int> ids_from(const py::handle& value, const std::string& what, size_t count) {
  if (value.is_none()) return std::vector<int>(count, 0);
  const py::array_t<int64_t> a = integer_array(value, what, 0);
  std::vector<int> ids;
  for (py::ssize_t i = 0; i < a.shape(0); ++i) ids.push_back(narrow(a.at(i), what));
  return ids;
}

inline std::vector<Vec3> points_from(const py::handle& value, const std::string& what) {
  const py::array a = as_numpy(value);
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw ParameterError(what + " must be an (n, 3) array, not " + shape_of(a));
  const auto d = a.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
  auto r = d.unchecked<2>();
  std::vector<Vec3> points;
  points.reserve(static_cast<size_t>(r.shape(0)));
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    points.emplace_back(r(i, 0), r(i, 1), r(i, 2));
    if (!points.back().allFinite())
      throw ParameterError(what + ": point " + std::to_string(i) + " is not finite");
  }
  return points;
}

template <size_t N>
void check_cells(const std::vector<std::array<int, N>>& cells, size_t num_vertices,
                 const char* what) {
  for (size_t i = 0; i < cells.size(); ++i)
    for (int v : cells[i])
      if (v < 0 || static_cast<size_t>(v) >= num_vertices)
        throw ParameterError(std::string(what) + " " + std::to_string(i) + " refers to vertex " +
                             std::to_string(v) + ", which does not exist (" +
                             std::to_string(num_vertices) + " vertices)");
}

}  // namespace voroseal::python

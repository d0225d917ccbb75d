#pragma once
/// @file
/// NumPy arrays in and out of the bindings: shape checks, float64 views without copies,
/// the few copies the C++ API needs (counted), and arrays that adopt C++ storage.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor::python {

namespace py = pybind11;

/// A C-contiguous float64 array.
using DoubleArray = py::array_t<double, py::array::c_style>;

/// How many times the bindings copied the data of an input array: a dtype or layout
/// conversion (e.g. float32 or Fortran order in), or a copy into the `Positions` that the
/// C++ API takes. Exposed as `tailor._input_copies()` so tests can check that float64
/// C-contiguous arrays go through without one where the API allows.
std::int64_t& input_copies();

/// `object` as a C-contiguous float64 array of shape (n, `columns`): the array itself
/// when it already is one (no copy), else a converted copy (counted). Throws ValueError
/// naming `name` when the shape is wrong or the values are not numbers.
DoubleArray float64_rows(py::handle object, const char* name, py::ssize_t columns = 3);

/// Copies (n, 3) float64 rows into `out`, resizing it (counted).
void copy_positions(const DoubleArray& rows, Positions& out);

/// `object` as (n, 3) positions: float64_rows() then copy_positions().
Positions to_positions(py::handle object, const char* name);

/// `object` as (n, 3) triangle faces of int32 vertex ids (any integer array or nested
/// sequence; ids outside the int32 range are a ValueError naming `name`).
FaceArray to_faces(py::handle object, const char* name);

/// `object` as lists of vertex ids (a sequence of sequences of integers). Throws ValueError
/// naming `name` on anything else.
std::vector<std::vector<Index>> to_index_lists(py::handle object, const char* name);

/// A NumPy view of `matrix`'s storage (no copy) that keeps `owner` alive; read-only unless
/// `writable`.
template <class Matrix>
py::array view_of(Matrix& matrix, py::handle owner, bool writable) {
  using Scalar = typename Matrix::Scalar;
  static_assert(Matrix::IsRowMajor || Matrix::ColsAtCompileTime == 1);
  py::array array(
      py::dtype::of<Scalar>(),
      {static_cast<py::ssize_t>(matrix.rows()), static_cast<py::ssize_t>(matrix.cols())},
      {static_cast<py::ssize_t>(sizeof(Scalar) * matrix.cols()),
       static_cast<py::ssize_t>(sizeof(Scalar))},
      matrix.data(), owner);
  if (!writable) array.attr("setflags")(py::arg("write") = false);
  return array;
}

/// A NumPy array that takes over `matrix` (moved to the heap, freed with the array).
template <class Matrix>
py::array adopt(Matrix&& matrix) {
  auto* owned = new std::decay_t<Matrix>(std::forward<Matrix>(matrix));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::decay_t<Matrix>*>(p); });
  return view_of(*owned, owner, true);
}

}  // namespace tailor::python

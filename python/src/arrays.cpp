#include "arrays.hpp"

#include <fmt/format.h>

#include <cstring>
#include <limits>
#include <string>

namespace tailor::python {
namespace {

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) {
    text += (i > 0 ? ", " : "") + std::to_string(array.shape(i));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// `object` as a NumPy array of any dtype (a view when it is one already).
py::array as_array(py::handle object, const char* name, const char* expected) {
  if (py::isinstance<py::array>(object)) return py::reinterpret_borrow<py::array>(object);
  try {
    return py::module_::import("numpy").attr("asarray")(object);
  } catch (const py::error_already_set&) {
    throw py::value_error(fmt::format("{} must be {}", name, expected));
  }
}

Index checked_index(long long value, const char* name) {
  if (value < std::numeric_limits<Index>::min() || value > std::numeric_limits<Index>::max()) {
    throw py::value_error(fmt::format("{} has vertex id {} outside the int32 range", name, value));
  }
  return static_cast<Index>(value);
}

}  // namespace

std::int64_t& input_copies() {
  static std::int64_t count = 0;
  return count;
}

DoubleArray float64_rows(py::handle object, const char* name, py::ssize_t columns) {
  const std::string expected = fmt::format("an array of shape (n, {}) of numbers", columns);
  const py::array array = as_array(object, name, expected.c_str());
  if (array.ndim() != 2 || array.shape(1) != columns) {
    throw py::value_error(
        fmt::format("{} must be {}, got shape {}", name, expected, shape_text(array)));
  }
  if (py::isinstance<DoubleArray>(array)) return py::reinterpret_borrow<DoubleArray>(array);
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::value_error(fmt::format("{} must be {}, got dtype {}", name, expected,
                                      py::str(array.dtype()).cast<std::string>()));
  }
  ++input_copies();
  return DoubleArray::ensure(array);
}

void copy_positions(const DoubleArray& rows, Positions& out) {
  ++input_copies();
  out.resize(rows.shape(0), 3);
  if (rows.size() > 0) std::memcpy(out.data(), rows.data(), sizeof(double) * rows.size());
}

Positions to_positions(py::handle object, const char* name) {
  Positions positions;
  copy_positions(float64_rows(object, name), positions);
  return positions;
}

FaceArray to_faces(py::handle object, const char* name) {
  const char* expected = "an array of shape (n, 3) of vertex ids";
  const py::array array = as_array(object, name, expected);
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw py::value_error(
        fmt::format("{} must be {}, got shape {}", name, expected, shape_text(array)));
  }
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u' && !(kind == 'f' && array.size() == 0)) {
    throw py::value_error(fmt::format("{} must be {}, got dtype {}", name, expected,
                                      py::str(array.dtype()).cast<std::string>()));
  }
  const auto ids = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(array);
  FaceArray faces(array.shape(0), 3);
  for (py::ssize_t i = 0; i < ids.size(); ++i) faces.data()[i] = checked_index(ids.data()[i], name);
  return faces;
}

std::vector<std::vector<Index>> to_index_lists(py::handle object, const char* name) {
  const auto fail = [name] {
    return py::value_error(fmt::format("{} must be a list of lists of vertex ids", name));
  };
  if (!py::isinstance<py::sequence>(object) || py::isinstance<py::str>(object)) throw fail();
  std::vector<std::vector<Index>> lists;
  for (py::handle item : py::reinterpret_borrow<py::sequence>(object)) {
    const py::array array = as_array(item, name, "a list of lists of vertex ids");
    const char kind = array.dtype().kind();
    if (array.ndim() != 1 || (kind != 'i' && kind != 'u' && array.size() > 0)) throw fail();
    const auto ids =
        py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(array);
    auto& list = lists.emplace_back();
    for (py::ssize_t i = 0; i < ids.size(); ++i) list.push_back(checked_index(ids.data()[i], name));
  }
  return lists;
}

}  // namespace tailor::python

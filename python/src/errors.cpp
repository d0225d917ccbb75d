#include "errors.hpp"

#include <fstream>

#include "tailor/geometry/error.hpp"

namespace tailor::python {

void bind_errors(py::module_& m) {
  // A subclass of ValueError, so `except ValueError` catches it too.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input (malformed file, invalid mesh, bad option); the message names the file "
      "and the problem, as the `tailor` command prints it.";
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const InputError& e) {
      input_error(e.what());
    }
  });
}

void with_file_errors(const std::filesystem::path& path, const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
      PyErr_SetString(PyExc_FileNotFoundError, e.what());
      throw py::error_already_set();
    }
    if (!std::ifstream(path) || std::filesystem::is_directory(path, ec)) {
      PyErr_SetString(PyExc_OSError, e.what());
      throw py::error_already_set();
    }
    throw;
  }
}

}  // namespace tailor::python

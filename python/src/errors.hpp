#pragma once
/// @file
/// How C++ errors reach Python: tailor::InputError becomes `tailor.InputError` (a
/// ValueError) with the message the CLI prints after "error: "; a file that cannot be
/// opened becomes an OSError (FileNotFoundError when it does not exist), same message.

#include <pybind11/pybind11.h>

#include <filesystem>
#include <functional>

namespace tailor::python {

namespace py = pybind11;

/// Registers `tailor.InputError` and the translator of tailor::InputError.
void bind_errors(py::module_& m);

/// Runs `read` (which reads `path`); an InputError raised while `path` cannot be opened
/// for reading is rethrown as OSError / FileNotFoundError with the same message.
void with_file_errors(const std::filesystem::path& path, const std::function<void()>& read);

}  // namespace tailor::python

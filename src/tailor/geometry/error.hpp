#pragma once
/// @file
/// The exception type for bad input.

#include <stdexcept>
#include <string>

namespace tailor {

/// Bad input (a malformed file, an invalid mesh, a bad option value). The message names
/// the file (where there is one) and the problem, and is fit to show to a user as is.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tailor

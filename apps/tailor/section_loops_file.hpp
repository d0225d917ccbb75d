#pragma once
/// @file
/// The `--observers` file of the detecting commands: radial-view section loops as JSON.

#include <string>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor::cli {

/// Reads `{"loops": [[vertex ids], ...]}` (one loop per observation point). Throws
/// InputError naming the file on a missing file, bad JSON or an unknown field.
std::vector<std::vector<Index>> read_section_loops(const std::string& path);

}  // namespace tailor::cli

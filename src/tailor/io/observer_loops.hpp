#pragma once
/// @file
/// Radial-view observer files (`tailor detect --observers FILE`): the section loops of a
/// tube-like garment, one loop of vertex ids per observation point.
///
/// Format: `{"loops": [[v, v, ...], ...]}` and nothing else; every id an integer (no
/// fraction, no exponent) in [0, number of mesh vertices); at least one loop, no loop
/// empty.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Reads an observers file for a mesh of `num_vertices` vertices. Throws InputError
/// naming the file and the offending entry (e.g. `loops[1][4]`) on any deviation from
/// the format, and as read_json_file() (json_file.hpp).
std::vector<std::vector<Index>> read_observer_loops(const std::filesystem::path& path,
                                                    Index num_vertices);

/// Checks and converts parsed observers JSON; `source` names it in errors.
std::vector<std::vector<Index>> parse_observer_loops(const nlohmann::json& json,
                                                     const std::string& source, Index num_vertices);

}  // namespace tailor

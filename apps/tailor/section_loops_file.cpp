/// @file
/// Reader of the `--observers` JSON file (shared by `tailor detect` and `tailor check`).

#include "section_loops_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tailor/geometry/error.hpp"

namespace tailor::cli {

std::vector<std::vector<Index>> read_section_loops(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw InputError(fmt::format("{}: cannot open", path));
  try {
    const nlohmann::json json = nlohmann::json::parse(file);
    if (!json.is_object() || !json.contains("loops") || !json["loops"].is_array()) {
      throw InputError(fmt::format("{}: expected an object with an array \"loops\"", path));
    }
    for (const auto& [key, value] : json.items()) {
      if (key != "loops") throw InputError(fmt::format("{}: unknown field \"{}\"", path, key));
    }
    return json["loops"].get<std::vector<std::vector<Index>>>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: {}", path, e.what()));
  }
}

}  // namespace tailor::cli

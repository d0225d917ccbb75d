/// @file
/// Observer files: strict checks, every error naming the file and the entry.

#include "tailor/io/observer_loops.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "tailor/geometry/error.hpp"
#include "tailor/io/excerpt.hpp"
#include "tailor/io/json_file.hpp"

namespace tailor {

std::vector<std::vector<Index>> parse_observer_loops(const nlohmann::json& json,
                                                     const std::string& source,
                                                     Index num_vertices) {
  const auto fail = [&](const std::string& problem) {
    throw InputError(fmt::format("{}: {}", source, problem));
  };
  if (!json.is_object()) {
    fail(fmt::format("expected an object {{\"loops\": [[vertex ids], ...]}}, got {} {}",
                     json.type_name(), json_excerpt(json)));
  }
  for (auto it = json.begin(); it != json.end(); ++it) {
    if (it.key() != "loops") fail(fmt::format("unknown field '{}'", excerpt(it.key())));
  }
  const auto loops = json.find("loops");
  if (loops == json.end()) fail("missing field 'loops'");
  if (!loops->is_array() || loops->empty()) {
    fail(fmt::format("'loops' must be a non-empty array of arrays of vertex ids, got {}",
                     json_excerpt(*loops)));
  }
  std::vector<std::vector<Index>> result;
  result.reserve(loops->size());
  for (std::size_t i = 0; i < loops->size(); ++i) {
    const nlohmann::json& loop = (*loops)[i];
    if (!loop.is_array() || loop.empty()) {
      fail(fmt::format("loops[{}] must be a non-empty array of vertex ids, got {}", i,
                       json_excerpt(loop)));
    }
    std::vector<Index>& ids = result.emplace_back();
    ids.reserve(loop.size());
    for (std::size_t j = 0; j < loop.size(); ++j) {
      const nlohmann::json& id = loop[j];
      // Only JSON integers: 2.5 is no vertex, and 1e30 would not convert.
      const bool in_range = (id.is_number_unsigned() &&
                             id.get<std::uint64_t>() < static_cast<std::uint64_t>(num_vertices)) ||
                            (id.is_number_integer() && !id.is_number_unsigned() &&
                             id.get<std::int64_t>() >= 0 && id.get<std::int64_t>() < num_vertices);
      if (!in_range) {
        fail(fmt::format("loops[{}][{}] must be a vertex id, an integer in [0, {}), got {}", i, j,
                         num_vertices, json_excerpt(id)));
      }
      ids.push_back(static_cast<Index>(id.get<std::int64_t>()));
    }
  }
  return result;
}

std::vector<std::vector<Index>> read_observer_loops(const std::filesystem::path& path,
                                                    Index num_vertices) {
  const nlohmann::json json = read_json_file(path);
  return with_json_errors(path.string(),
                          [&] { return parse_observer_loops(json, path.string(), num_vertices); });
}

}  // namespace tailor

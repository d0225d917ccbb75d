/// @file
/// Per-frame sums of the substep records of a simulation run.

#include "view/step_stats.hpp"

#include <fmt/format.h>

#include <set>
#include <string>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"

namespace tailor::cli {
namespace {

const std::set<std::string>& ignored_fields() {
  static const std::set<std::string> fields{"frame", "substep", "time", "solver.residual"};
  return fields;
}

// Adds every numeric leaf of `record` (booleans excluded) to `series[name][frame]`.
void add_numbers(const nlohmann::json& record, const std::string& prefix, std::size_t frame,
                 std::size_t num_frames, nlohmann::json& series) {
  for (const auto& [key, value] : record.items()) {
    const std::string name = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object()) {
      add_numbers(value, name, frame, num_frames, series);
      continue;
    }
    if (!value.is_number() || ignored_fields().count(name) != 0) continue;
    nlohmann::json& values = series[name];
    if (values.is_null()) values = nlohmann::json::array();
    while (values.size() < num_frames) values.push_back(nullptr);
    nlohmann::json& slot = values[frame];
    slot = slot.is_null() ? value.get<double>() : slot.get<double>() + value.get<double>();
  }
}

}  // namespace

nlohmann::json read_frame_stats(const std::filesystem::path& path, int num_frames) {
  const std::string text = read_file_bytes(path);
  nlohmann::json series = nlohmann::json::object();
  std::size_t line_number = 0, start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto fail = [&](const std::string& problem) {
      throw InputError(fmt::format("{}:{}: {}", path.string(), line_number, problem));
    };
    nlohmann::json record;
    try {
      record = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception& e) {
      fail(fmt::format("not valid JSON ({})", e.what()));
    }
    if (!record.is_object()) fail("expected a JSON object");
    const auto frame = record.find("frame");
    if (frame == record.end() || !frame->is_number_integer()) fail("no integer \"frame\"");
    const auto k = frame->get<std::int64_t>();
    if (k < 1 || k >= num_frames) {
      fail(fmt::format("frame {} is outside the frames written (1 to {})", k, num_frames - 1));
    }
    add_numbers(record, "", static_cast<std::size_t>(k), static_cast<std::size_t>(num_frames),
                series);
  }
  return {{"series", series}};
}

nlohmann::json single_step_stats(const nlohmann::json& detection_stats) {
  nlohmann::json series = nlohmann::json::object();
  if (detection_stats.is_object()) add_numbers({{"detection", detection_stats}}, "", 1, 2, series);
  return {{"series", series}};
}

}  // namespace tailor::cli

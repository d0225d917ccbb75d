/// @file
/// Checked JSON reads with messages that name the file and the place.

#include "view/json_input.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"

namespace tailor::cli {

nlohmann::json read_json_file(const std::filesystem::path& path) {
  const std::string text = read_file_bytes(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not valid JSON ({})", path.string(), e.what()));
  }
}

void fail_json(const std::filesystem::path& file, const std::string& where,
               const std::string& problem) {
  throw InputError(fmt::format("{}: {}: {}", file.string(), where, problem));
}

std::int64_t json_integer(const nlohmann::json& value, const std::filesystem::path& file,
                          const std::string& where, std::int64_t lo, std::int64_t hi) {
  if (!value.is_number_integer()) {
    fail_json(file, where, fmt::format("expected an integer, found {}", value.dump()));
  }
  // Unsigned values above INT64_MAX would wrap: compare them before converting.
  if (value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) {
    fail_json(file, where, fmt::format("{} is out of range [{}, {}]", value.dump(), lo, hi));
  }
  const auto number = value.get<std::int64_t>();
  if (number < lo || number > hi) {
    fail_json(file, where, fmt::format("{} is out of range [{}, {}]", number, lo, hi));
  }
  return number;
}

double json_number(const nlohmann::json& value, const std::filesystem::path& file,
                   const std::string& where, double lo, double hi) {
  if (!value.is_number()) {
    fail_json(file, where, fmt::format("expected a number, found {}", value.dump()));
  }
  const auto number = value.get<double>();
  if (!std::isfinite(number) || number < lo || number > hi) {
    fail_json(file, where, fmt::format("{} is out of range [{}, {}]", number, lo, hi));
  }
  return number;
}

const nlohmann::json& json_array(const nlohmann::json& value, const std::filesystem::path& file,
                                 const std::string& where, std::int64_t size) {
  if (!value.is_array()) {
    fail_json(file, where, fmt::format("expected an array, found {}", value.type_name()));
  }
  if (size >= 0 && static_cast<std::int64_t>(value.size()) != size) {
    fail_json(file, where, fmt::format("expected {} elements, found {}", size, value.size()));
  }
  return value;
}

const nlohmann::json& json_field(const nlohmann::json& object, const std::string& key,
                                 const std::filesystem::path& file) {
  if (!object.is_object()) {
    throw InputError(
        fmt::format("{}: expected a JSON object, found {}", file.string(), object.type_name()));
  }
  const auto it = object.find(key);
  if (it == object.end()) {
    throw InputError(fmt::format("{}: missing field \"{}\"", file.string(), key));
  }
  return *it;
}

}  // namespace tailor::cli

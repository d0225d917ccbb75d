#pragma once
/// @file
/// Checked reads of the JSON files `tailor view` takes as input: every failure is an
/// InputError naming the file and the place in it (e.g. `vertex_face[3][1]`).

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace tailor::cli {

/// Parses the whole file. Throws InputError naming the file if it cannot be opened or is
/// not valid JSON.
nlohmann::json read_json_file(const std::filesystem::path& path);

/// Throws InputError "`file`: `where`: `problem`".
[[noreturn]] void fail_json(const std::filesystem::path& file, const std::string& where,
                            const std::string& problem);

/// `value` as an integer in [lo, hi]; otherwise an InputError naming `file` and `where`.
std::int64_t json_integer(const nlohmann::json& value, const std::filesystem::path& file,
                          const std::string& where, std::int64_t lo, std::int64_t hi);

/// `value` as a finite number in [lo, hi]; otherwise an InputError naming `file` and `where`.
double json_number(const nlohmann::json& value, const std::filesystem::path& file,
                   const std::string& where, double lo, double hi);

/// `value` as an array (of exactly `size` elements unless `size` is -1).
const nlohmann::json& json_array(const nlohmann::json& value, const std::filesystem::path& file,
                                 const std::string& where, std::int64_t size = -1);

/// Field `key` of the object `object` (which must be an object), or an InputError if absent.
const nlohmann::json& json_field(const nlohmann::json& object, const std::string& key,
                                 const std::filesystem::path& file);

}  // namespace tailor::cli

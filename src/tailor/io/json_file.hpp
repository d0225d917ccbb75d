#pragma once
/// @file
/// JSON input files (scene files, radial-view observers) read defensively: every failure
/// is an InputError naming the file, whatever nlohmann::json throws, and no input can
/// overflow the stack or the memory budget.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>

#include "tailor/geometry/error.hpp"

namespace tailor {

/// Deepest nesting of arrays and objects accepted in a JSON input (none of ours needs
/// more than 4).
inline constexpr int kMaxJsonDepth = 64;

/// Parses JSON text; `source` names it in errors. Throws InputError "{source}: ..." on
/// malformed JSON, a number out of the range of a double (e.g. `1e400`), nesting deeper
/// than kMaxJsonDepth, or text whose parsed form could exceed the memory budget (32
/// bytes per byte of text is budgeted).
nlohmann::json parse_json_text(std::string_view text, const std::string& source);

/// Reads (maps) and parses a JSON file as parse_json_text() does. Throws InputError
/// naming the file if it cannot be opened.
nlohmann::json read_json_file(const std::filesystem::path& path);

/// A short printable rendering of `value` for error messages: at most ~40 bytes, built
/// without walking (or recursing into) more of the value than it shows.
std::string json_excerpt(const nlohmann::json& value);

/// The message of a nlohmann::json exception without its `[json.exception...]` prefix,
/// cut so that any input it quotes stays short.
std::string json_error_message(const nlohmann::json::exception& error);

/// Runs `body()` and turns any nlohmann::json::exception escaping it into an InputError
/// "{source}: ..." (InputErrors pass through unchanged).
template <typename Body>
decltype(auto) with_json_errors(const std::string& source, Body&& body) {
  try {
    return std::forward<Body>(body)();
  } catch (const nlohmann::json::exception& error) {
    throw InputError(source + ": " + json_error_message(error));
  }
}

}  // namespace tailor

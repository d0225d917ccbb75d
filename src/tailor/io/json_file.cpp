/// @file
/// Defensive JSON parsing: a depth-limited parse, budgeted size, short messages.

#include "tailor/io/json_file.hpp"

#include <fmt/format.h>

#include "tailor/io/excerpt.hpp"
#include "tailor/io/input_file.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {
namespace {

/// Thrown from the parser callback to stop at the first too-deep value.
struct TooDeep {};

/// Bytes of parsed JSON per byte of text, at worst: `{}` and `[]` cost a json value and
/// a heap container (16 + 48 bytes) for 3 bytes of text (with the comma).
constexpr double kJsonBytesPerTextByte = 32;

/// Appends a rendering of `value` to `out`, stopping once `out` is longer than `limit`
/// or below `depth_left` levels (shown as "...").
void render(const nlohmann::json& value, std::string& out, std::size_t limit, int depth_left) {
  if (out.size() > limit) return;
  if (value.is_string()) {
    out += '"';
    out += excerpt(value.get_ref<const std::string&>(), limit - out.size() + 1);
    out += '"';
    return;
  }
  if (!value.is_structured()) {
    out += value.dump();  // a number, a boolean or null: short
    return;
  }
  if (depth_left == 0) {
    out += "...";
    return;
  }
  const bool object = value.is_object();
  out += object ? '{' : '[';
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (out.size() > limit) return;
    if (!first) out += ", ";
    first = false;
    if (object) out += '"' + excerpt(it.key(), limit) + "\": ";
    render(*it, out, limit, depth_left - 1);
  }
  out += object ? '}' : ']';
}

}  // namespace

nlohmann::json parse_json_text(std::string_view text, const std::string& source) {
  check_memory_budget(kJsonBytesPerTextByte * static_cast<double>(text.size()),
                      fmt::format("parsing {} ({} of JSON)", source,
                                  format_bytes(static_cast<double>(text.size()))));
  const auto limit_depth = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (depth > kMaxJsonDepth) throw TooDeep{};
    return true;
  };
  try {
    return nlohmann::json::parse(text.begin(), text.end(), limit_depth);
  } catch (const TooDeep&) {
    throw InputError(fmt::format("{}: JSON nested deeper than {} levels", source, kMaxJsonDepth));
  } catch (const nlohmann::json::exception& error) {
    throw InputError(fmt::format("{}: malformed JSON: {}", source, json_error_message(error)));
  }
}

nlohmann::json read_json_file(const std::filesystem::path& path) {
  const InputFile file(path);
  return parse_json_text(file.bytes(), path.string());
}

std::string json_excerpt(const nlohmann::json& value) {
  std::string out;
  render(value, out, kExcerptBytes, 4);
  if (out.size() > kExcerptBytes) out = out.substr(0, kExcerptBytes - 3) + "...";
  return out;
}

std::string json_error_message(const nlohmann::json::exception& error) {
  std::string_view message = error.what();
  if (message.starts_with("[json.exception.")) {
    if (const auto end = message.find("] "); end != std::string_view::npos) {
      message.remove_prefix(end + 2);
    }
  }
  // Long enough for nlohmann's own words plus ~40 bytes of the token it quotes.
  return excerpt(message, 160);
}

}  // namespace tailor

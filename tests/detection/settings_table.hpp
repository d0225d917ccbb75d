#pragma once
// docs/settings.md, rendered from the two lists (kDetectionSettings, kDetectionStatFields):
// test_field_lists.cpp checks the file against it and rewrites it with TAILOR_UPDATE_DOCS=1.

#include <fmt/format.h>

#include <string>
#include <string_view>

#include "tailor/detection/detection_config.hpp"
#include "tailor/detection/detection_stats.hpp"

namespace tailor::testing {

/// The command that regenerates docs/settings.md.
inline constexpr std::string_view kSettingsDocsCommand =
    "TAILOR_UPDATE_DOCS=1 build/release/tests/tailor_test_detection "
    "--gtest_filter='FieldLists.DocsTableIsCurrent'";

inline std::string markdown_cell(std::string_view text) {
  std::string cell;
  for (const char c : text) cell += c == '|' ? std::string("\\|") : std::string(1, c);
  return cell;
}

inline std::string setting_type(const DetectionSetting& setting) {
  return std::visit(
      [](auto member) -> std::string {
        using T = std::remove_cvref_t<decltype(DetectionConfig{}.*member)>;
        if constexpr (std::is_same_v<T, bool>) return "bool";
        if constexpr (std::is_same_v<T, int>) return "int";
        return "double";
      },
      setting.member);
}

inline std::string setting_range(const DetectionSetting& setting) {
  if (setting_type(setting) == "bool") return "on / off";
  if (setting.max == kUnbounded) return fmt::format("≥ {}", setting.min);
  return fmt::format("{} to {}", setting.min, setting.max);
}

inline std::string setting_cli(const DetectionSetting& setting) {
  if (setting.cli.empty()) return "—";
  if (setting_type(setting) == "bool") return fmt::format("`--{0}`, `--no-{0}`", setting.cli);
  return fmt::format("`--{} N`", setting.cli);
}

inline std::string settings_table() {
  std::string text =
      "| setting | type | default | range | CLI | effect | what it does |\n"
      "|---|---|---|---|---|---|---|\n";
  const DetectionConfig defaults;
  for (const DetectionSetting& s : kDetectionSettings) {
    text += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} |\n", s.name, setting_type(s),
                        setting_value(defaults, s), setting_range(s), setting_cli(s),
                        to_string(s.effect), markdown_cell(s.help));
  }
  return text;
}

// The settings the presets differ in, one column per preset.
inline std::string presets_table() {
  std::string text = "| setting |";
  std::string rule = "|---|";
  for (const std::string& preset : DetectionConfig::preset_names()) {
    text += fmt::format(" `{}` |", preset);
    rule += "---|";
  }
  text += "\n" + rule + "\n";
  for (const DetectionSetting& s : kDetectionSettings) {
    std::string row = fmt::format("| `{}` |", s.name);
    bool differs = false;
    const std::string paper = setting_value(DetectionConfig::preset("paper"), s);
    for (const std::string& preset : DetectionConfig::preset_names()) {
      const std::string value = setting_value(DetectionConfig::preset(preset), s);
      differs = differs || value != paper;
      row += fmt::format(" {} |", value == "true" ? "on" : value == "false" ? "off" : value);
    }
    if (differs) text += row + "\n";
  }
  return text;
}

inline std::string stats_table() {
  std::string text =
      "| field | unit | stage | what it counts |\n"
      "|---|---|---|---|\n";
  for (const DetectionStatField& f : kDetectionStatFields) {
    text += fmt::format("| `{}` | {} | {} | {} |\n", f.name, f.is_time() ? "ms" : "count", f.stage,
                        markdown_cell(f.help));
  }
  return text;
}

/// The whole of docs/settings.md.
inline std::string settings_markdown() {
  return fmt::format(
      "# Settings and statistics\n\n"
      "<!-- Generated: do not edit. The lists are TAILOR_DETECTION_SETTINGS "
      "(src/tailor/detection/detection_config.hpp) and TAILOR_DETECTION_STATS "
      "(src/tailor/detection/detection_stats.hpp); regenerate with\n"
      "  {}\n-->\n\n"
      "Every setting of `DetectionConfig` and every field of `DetectionStats`, from the one "
      "list each is declared in. The same lists make the command-line options (`tailor "
      "detect`, `check`, `view`), the Python properties (`tailor.DetectionConfig`, "
      "`DetectionConfig.settings()`, `DetectionResult.stat_fields()`) and the JSON keys "
      "(`tailor detect --json`: `config`, `stats`); the test `FieldLists.*` "
      "(tests/detection/test_field_lists.cpp, python/tests/test_field_lists.py, "
      "tests/cli/test_cli_detect.cpp) fails when one of them misses a field. Adding one: "
      "docs/design.md, \"Adding a setting\".\n\n"
      "## DetectionConfig\n\n"
      "Effect: **work only**: every value reports exactly the brute-force collisions, only "
      "the work differs (the test `DetectorVsBruteForce` runs every combination); **output "
      "only**: changes what the result holds beside the collisions (statistics, candidate "
      "pairs), never the collisions; **unsound when off**: turned off it can miss collisions "
      "(`contour_test` with `normal_cones` on: the cone alone is no certificate, "
      "`NormalConeCulling.ContourTestIsWhatKeepsTheRibbonCollisions`), kept only to measure "
      "what the test costs (no preset turns the cones on without it); **defines the result**: "
      "changes which pairs count as colliding (none yet; e.g. a thickness): exact for its "
      "value, brute force must be given the same. The defaults are the `paper` "
      "preset.\n\n{}\n"
      "The presets (`--method`, `DetectionConfig::preset`) differ in:\n\n{}\n"
      "## DetectionStats\n\n"
      "Per step (a SequenceCheck or simulation sums them over steps); counts are exact, times "
      "in milliseconds.\n\n{}",
      kSettingsDocsCommand, settings_table(), presets_table(), stats_table());
}

}  // namespace tailor::testing

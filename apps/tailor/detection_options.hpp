#pragma once
/// @file
/// The `--method` preset and one option per DetectionConfig setting (kDetectionSettings:
/// `--cones/--no-cones`-style switches, `--threads N`), shared by every command that detects.

#include <CLI/CLI.hpp>
#include <cctype>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "tailor/detection/detection_config.hpp"
#include "thread_limit.hpp"

namespace tailor::cli {

/// Options selecting a DetectionConfig: a preset and single-setting overrides, applied in
/// the order given (the last of `--cones --no-cones` wins).
struct DetectionOptions {
  std::string method = "paper";

  /// Adds `--method` and an option for every setting of kDetectionSettings that has a CLI
  /// spelling to `command`.
  void add_to(CLI::App& command) {
    command.add_option("--method", method, "Culling preset: basic, curtis, tang, paper")
        ->check(CLI::IsMember(DetectionConfig::preset_names()))
        ->capture_default_str();
    for (const DetectionSetting& setting : kDetectionSettings) {
      if (setting.cli.empty()) continue;
      std::visit([&](auto member) { add_option(command, setting, member); }, setting.member);
    }
  }

  /// The preset with the overrides applied.
  DetectionConfig config() const {
    DetectionConfig config = DetectionConfig::preset(method);
    for (const auto& apply : m_overrides) apply(config);
    return config;
  }

 private:
  std::vector<std::function<void(DetectionConfig&)>> m_overrides;

  // A switch: `--NAME` turns it on, `--no-NAME` off.
  void add_option(CLI::App& command, const DetectionSetting& setting,
                  bool DetectionConfig::*member) {
    const std::string name(setting.cli), help(setting.help);
    for (const bool on : {true, false}) {
      command.add_flag_callback(
          (on ? "--" : "--no-") + name,
          [this, member, on] {
            m_overrides.emplace_back([member, on](DetectionConfig& c) { c.*member = on; });
          },
          (on ? "Turn on " : "Turn off ") + help);
    }
  }

  // A number: `--NAME VALUE` within the setting's range (`--threads`: at most
  // max_threads(), thread_limit.hpp).
  template <class T>
  void add_option(CLI::App& command, const DetectionSetting& setting, T DetectionConfig::*member) {
    static_assert(std::is_arithmetic_v<T>);
    std::string help(setting.help);
    if (!help.empty()) help[0] = static_cast<char>(std::toupper(help[0]));
    CLI::Option* option = command.add_option_function<T>(
        "--" + std::string(setting.cli),
        [this, member](const T& value) {
          m_overrides.emplace_back([member, value](DetectionConfig& c) { c.*member = value; });
        },
        help);
    if (setting.name == "threads") {
      option->check(thread_count_validator());
    } else {
      const T max =
          setting.max == kUnbounded ? std::numeric_limits<T>::max() : static_cast<T>(setting.max);
      option->check(CLI::Range(static_cast<T>(setting.min), max));
    }
  }
};

}  // namespace tailor::cli

#pragma once
/// @file
/// The `--method` preset and per-stage switches shared by every command that detects.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "tailor/detection/detection_config.hpp"
#include "thread_limit.hpp"

namespace tailor::cli {

/// Options selecting a DetectionConfig: a preset and single-stage overrides.
struct DetectionOptions {
  std::string method = "paper";
  std::optional<bool> normal_cones, contour_test, adjacency_culling, feature_assignment,
      primitive_boxes, coplanarity_filter, projection_filter, radial_view;
  int threads = 0;

  /// Adds `--method`, `--threads` and `--cones/--no-cones`-style switches to `command`.
  void add_to(CLI::App& command) {
    command.add_option("--method", method, "Culling preset: basic, curtis, tang, paper")
        ->check(CLI::IsMember(DetectionConfig::preset_names()))
        ->capture_default_str();
    command.add_option("--threads", threads, "Worker threads (0: all cores)")
        ->check(thread_count_validator());
    add_switch(command, "cones", normal_cones, "continuous normal-cone culling");
    add_switch(command, "contour", contour_test,
               "the contour test of cone culling (off is unsound; for comparison only)");
    add_switch(command, "adjacency", adjacency_culling, "adjacency culling + isolated set");
    add_switch(command, "assignment", feature_assignment, "feature assignment");
    add_switch(command, "primitive-boxes", primitive_boxes, "primitive bounding boxes");
    add_switch(command, "filter", coplanarity_filter, "non-coplanarity filter");
    add_switch(command, "projection", projection_filter, "projection filter");
    add_switch(command, "radial", radial_view, "radial-view culling");
  }

  /// The preset with the overrides applied.
  DetectionConfig config() const {
    DetectionConfig config = DetectionConfig::preset(method);
    auto apply = [](bool& field, const std::optional<bool>& value) {
      if (value) field = *value;
    };
    apply(config.normal_cones, normal_cones);
    apply(config.contour_test, contour_test);
    apply(config.adjacency_culling, adjacency_culling);
    apply(config.feature_assignment, feature_assignment);
    apply(config.primitive_boxes, primitive_boxes);
    apply(config.coplanarity_filter, coplanarity_filter);
    apply(config.projection_filter, projection_filter);
    apply(config.radial_view, radial_view);
    config.threads = threads;
    return config;
  }

 private:
  static void add_switch(CLI::App& command, const std::string& name, std::optional<bool>& value,
                         const std::string& what) {
    command.add_flag_callback(
        "--" + name, [&value] { value = true; }, "Turn on " + what);
    command.add_flag_callback(
        "--no-" + name, [&value] { value = false; }, "Turn off " + what);
  }
};

}  // namespace tailor::cli

/// @file
/// `tailor view DIR` / `tailor view --detect FILE.json T0 T1`: writes a web page (three.js)
/// that plays a simulation or shows one detected step, with its contacts and statistics.

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "detection_options.hpp"
#include "tailor/geometry/error.hpp"
#include "view/view_input.hpp"
#include "view/view_writer.hpp"

namespace tailor::cli {
namespace {

namespace fs = std::filesystem;

struct ViewArgs {
  std::vector<std::string> inputs;
  std::string detect_json;
  std::string out;
  bool no_candidates = false;
  DetectionOptions detection;
};

int run_view(const ViewArgs& args) {
  ViewInput input;
  fs::path out;
  if (args.detect_json.empty()) {
    if (args.inputs.size() != 1) {
      throw InputError(fmt::format(
          "view: expected one folder written by `tailor simulate` (got {} arguments; for a "
          "detected step use --detect FILE.json T0 T1)",
          args.inputs.size()));
    }
    input = open_simulation_output(args.inputs[0]);
    out = args.out.empty() ? fs::path(args.inputs[0]) / "view" : fs::path(args.out);
  } else {
    if (args.inputs.size() != 2) {
      throw InputError(
          fmt::format("view --detect {}: expected the two meshes of the step, T0 and T1 (got {})",
                      args.detect_json, args.inputs.size()));
    }
    std::optional<DetectionConfig> candidates;
    if (!args.no_candidates) candidates = args.detection.config();
    input = open_detection_output(args.detect_json, args.inputs[0], args.inputs[1], candidates);
    out = args.out.empty() ? fs::path(args.detect_json).parent_path() / "view" : fs::path(args.out);
  }
  const ViewOutput written = write_view(input, out);
  const fs::path page = fs::absolute(written.index_html).lexically_normal();
  fmt::print("wrote {} frames ({:.1f} MB) into {}\n", written.frames,
             static_cast<double>(written.bytes) / 1e6, page.parent_path().string());
  fmt::print("open file://{}\n", page.string());
  fmt::print("or serve it: python3 -m http.server -d '{}' and open http://localhost:8000/\n",
             page.parent_path().string());
  return kSuccess;
}

const CommandRegistration view_registration{
    "view", [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<ViewArgs>();
      CLI::App* command = app.add_subcommand(
          "view",
          "Write a web page (three.js; opens from file:// or any static server) that plays a "
          "simulation or shows one detected step: scrub frames, orbit, candidate triangles "
          "(red), colliding VF/EE pairs at their time of impact, radial-view clusters and "
          "observers, per-frame statistics");
      command->footer(
          "Inputs:\n"
          "  tailor view DIR                        DIR written by `tailor simulate --out DIR`\n"
          "  tailor view --detect FILE.json T0 T1   FILE.json written by `tailor detect T0 T1 "
          "--json FILE.json`\n"
          "The page goes to --out (default DIR/view, or view/ beside FILE.json): index.html, "
          "viewer.js, data/.");
      command->add_option("INPUT", args->inputs,
                          "The simulation output folder, or T0 T1 with --detect");
      command->add_option("--detect", args->detect_json,
                          "Show one step detected by `tailor detect ... --json FILE`");
      command->add_option("--out", args->out, "Folder to write the page into");
      command->add_flag("--no-candidates", args->no_candidates,
                        "With --detect: do not rerun the culling to find the candidate "
                        "triangles (the red overlay)");
      args->detection.add_to(*command);
      return [args] { return run_view(*args); };
    }};

}  // namespace
}  // namespace tailor::cli

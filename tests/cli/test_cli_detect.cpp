/// @file
/// `tailor detect`: one step between two frames, and its contract on bad input.

#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "tailor/detection/detection_config.hpp"

namespace tailor::test {
namespace {

const std::string kT0 = quoted(data_file("thick-cloth/t0.ply"));
const std::string kT1 = quoted(data_file("thick-cloth/t1.ply"));

TEST(CliDetect, Help) {
  expect_help("detect", {"MESH_T0", "MESH_T1", "--method", "--json"});
}

TEST(CliDetect, StepWithJsonOutput) {
  TempDir dir;
  const RunResult r = run_cli("detect " + kT0 + " " + kT1 + " --json " + quoted(dir / "out.json"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, {"mesh       : 233 vertices, 404 faces", "collisions :"});
  const std::string json = read_bytes(dir / "out.json");
  expect_contains(json, {"\"collisions\"", "\"vertex_face\"", "\"edge_edge\"", "\"stats\""});
}

// Whether `help` lists `option` as a whole word (`--cones`, not the tail of `--no-cones`).
bool lists_option(const std::string& help, const std::string& option) {
  const auto part_of_name = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-';
  };
  for (std::size_t at = help.find(option); at != std::string::npos;
       at = help.find(option, at + 1)) {
    const std::size_t end = at + option.size();
    if ((at == 0 || !part_of_name(help[at - 1])) &&
        (end == help.size() || !part_of_name(help[end]))) {
      return true;
    }
  }
  return false;
}

// Every setting of kDetectionSettings with a CLI spelling has its option(s), and each reaches
// the detector: one run changes every setting from the preset's value, and the `config` of
// `--json` (every setting) shows each changed (the field-list test of the CLI surface).
TEST(FieldLists, CliHasEverySetting) {
  std::vector<std::string> options;
  std::string changes;
  const DetectionConfig paper = DetectionConfig::preset("paper");
  for (const DetectionSetting& s : kDetectionSettings) {
    if (s.cli.empty()) continue;
    const std::string cli(s.cli);
    const std::string value = setting_value(paper, s);
    if (value == "true" || value == "false") {
      options.insert(options.end(), {"--" + cli, "--no-" + cli});
      changes += (value == "true" ? " --no-" : " --") + cli;
    } else {
      options.push_back("--" + cli);
      changes += " --" + cli + " " + std::to_string(std::stoi(value) + 1);
    }
  }
  const RunResult help = run_cli("detect --help");
  for (const std::string& option : options) {
    EXPECT_TRUE(lists_option(help.output, option)) << "detect --help misses " << option;
  }
  TempDir dir;
  const RunResult r =
      run_cli("detect " + kT0 + " " + kT1 + changes + " --json " + quoted(dir / "out.json"));
  ASSERT_EQ(r.exit_code, 0) << changes << "\n" << r.output;
  const nlohmann::json config = nlohmann::json::parse(read_bytes(dir / "out.json"))["config"];
  EXPECT_EQ(config.size(), kDetectionSettings.size()) << config.dump();
  for (const DetectionSetting& s : kDetectionSettings) {
    const std::string name(s.name);
    ASSERT_TRUE(config.contains(name)) << "tailor detect --json: config misses " << name;
    if (s.cli.empty()) {
      EXPECT_EQ(config[name].dump(), setting_value(paper, s)) << name;
    } else {
      EXPECT_NE(config[name].dump(), setting_value(paper, s))
          << name << ": the CLI did not change it (" << changes << ")";
    }
  }
}

TEST(CliDetect, UnknownOptionAndBadValues) {
  expect_usage_error("detect " + kT0 + " " + kT1 + " --no-such-option", {"--no-such-option"});
  expect_usage_error("detect " + kT0 + " " + kT1 + " --method fastest", {"fastest"});
  expect_usage_error("detect " + kT0 + " " + kT1 + " --threads -3", {"--threads"});
  expect_usage_error("detect " + kT0);
}

TEST(CliDetect, BadFilesAreNamed) {
  TempDir dir;
  expect_usage_error("detect " + quoted(dir / "absent.ply") + " " + kT1, {"absent.ply"});
  const auto cut = truncated_copy(dir, "thick-cloth/t1.ply", "cut.ply");
  expect_usage_error("detect " + kT0 + " " + quoted(cut), {"cut.ply", "truncated"});
  // Same file format, another mesh: the topologies differ.
  expect_usage_error("detect " + kT0 + " " + quoted(data_file("cloth-funnel/frames/228.ply")),
                     {"t0.ply", "228.ply", "topology"});
  { std::ofstream(dir / "loops.json") << "{\"loops\": [[0, 1, \"two\"]]}"; }
  expect_usage_error("detect " + kT0 + " " + kT1 + " --observers " + quoted(dir / "loops.json"),
                     {"loops.json"});
}

}  // namespace
}  // namespace tailor::test

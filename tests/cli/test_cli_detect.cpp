/// @file
/// `tailor detect`: one step between two frames, and its contract on bad input.

#include <fstream>

#include "cli_test_support.hpp"

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

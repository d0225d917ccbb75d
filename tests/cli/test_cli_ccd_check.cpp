/// @file
/// `tailor ccd-check`: exact CCD against reference queries, and its contract on bad input.

#include <fstream>

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliCcdCheck, Help) {
  expect_help("ccd-check", {"--truth"});
}

TEST(CliCcdCheck, ReferenceQueriesWithTruth) {
  const RunResult r =
      run_cli("ccd-check " + quoted(data_file("ccd-queries/unit-tests/edge-edge/data_0_0.csv")) +
              " " + quoted(data_file("cloth-funnel/queries/227vf.csv")) + " --truth " +
              quoted(data_file("cloth-funnel/mma_bool/227vf_mma_bool.json")));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, {"fn=0 fp=0"});
}

TEST(CliCcdCheck, UnknownOptionAndMissingTruth) {
  const std::string queries = quoted(data_file("cloth-funnel/queries/227ee.csv"));
  expect_usage_error("ccd-check " + queries + " --no-such-option", {"--no-such-option"});
  expect_usage_error("ccd-check " + queries, {"truth"});  // this file has no truth column
  expect_usage_error("ccd-check");
}

TEST(CliCcdCheck, BadFilesAreNamed) {
  TempDir dir;
  expect_usage_error("ccd-check " + quoted(dir / "absent_ee.csv"), {"absent_ee.csv"});
  std::filesystem::create_directories(dir / "edge-edge");
  { std::ofstream(dir / "edge-edge" / "broken.csv") << "1,1,2,1,3,1,0\n1,1,2,x,3,1,0\n"; }
  expect_usage_error("ccd-check " + quoted(dir / "edge-edge" / "broken.csv"), {"broken.csv"});
  const auto cut = truncated_copy(dir, "cloth-funnel/mma_bool/227ee_mma_bool.json", "cut.json");
  expect_usage_error("ccd-check " + quoted(data_file("cloth-funnel/queries/227ee.csv")) +
                         " --truth " + quoted(cut),
                     {"cut.json"});
}

}  // namespace
}  // namespace tailor::test

/// @file
/// `tailor info`: the counts of a mesh, and its contract on bad input.

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliInfo, Help) {
  expect_help("info", {"mesh", "Usage"});
}

TEST(CliInfo, ReferenceMesh) {
  const RunResult r = run_cli("info " + quoted(data_file("cloth-funnel/frames/227.ply")));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, {"vertices:", "9450", "faces:", "18484", "edges:", "boundary loops:",
                             "components:", "manifold:", "bounding box"});
}

TEST(CliInfo, TruncatedFileExitsWithUsageError) {
  TempDir dir;
  const auto cut = truncated_copy(dir, "thick-cloth/t0.ply", "cut.ply");
  expect_usage_error("info " + quoted(cut), {"cut.ply", "truncated"});
}

TEST(CliInfo, MissingFileAndBadOptions) {
  TempDir dir;
  expect_usage_error("info " + quoted(dir / "absent.obj"), {"absent.obj", "cannot open"});
  expect_usage_error("info --no-such-option x.obj", {"--no-such-option"});
  expect_usage_error("info");
}

}  // namespace
}  // namespace tailor::test

/// @file
/// `tailor check-intersections`: the static intersection check, and its contract on bad input.

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliCheckIntersections, Help) {
  expect_help("check-intersections", {"mesh", "obstacle", "--max-pairs"});
}

TEST(CliCheckIntersections, ReferenceMesh) {
  const RunResult r = run_cli("check-intersections " + quoted(data_file("thick-cloth/t0.ply")));
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;  // 1: intersecting
  expect_contains(r.output, {"self intersections:", "result:"});
}

TEST(CliCheckIntersections, UnknownOptionAndBadFiles) {
  TempDir dir;
  const std::string mesh = quoted(data_file("thick-cloth/t0.ply"));
  expect_usage_error("check-intersections " + mesh + " --no-such-option", {"--no-such-option"});
  expect_usage_error("check-intersections");
  expect_usage_error("check-intersections " + quoted(dir / "absent.obj"), {"absent.obj"});
  const auto cut = truncated_copy(dir, "thick-cloth/t1.ply", "cut.ply");
  expect_usage_error("check-intersections " + mesh + " " + quoted(cut), {"cut.ply", "truncated"});
}

}  // namespace
}  // namespace tailor::test

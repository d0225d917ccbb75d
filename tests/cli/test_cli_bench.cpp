/// @file
/// `tailor bench`: its contract on bad input (the runs themselves are benchmarks, not tests).

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliBench, Help) {
  expect_help("bench", {"paper", "scale"});
  expect_help("bench paper", {"--scene", "--frames", "--out"});
  expect_help("bench scale", {"--max-triangles", "--repetitions", "--min-seconds"});
}

TEST(CliBench, UnknownOptionAndBadValues) {
  expect_usage_error("bench paper --no-such-option", {"--no-such-option"});
  expect_usage_error("bench paper --frames 0", {"--frames"});
  expect_usage_error("bench scale --max-triangles 5", {"--max-triangles"});
  expect_usage_error("bench scale --repetitions 1000", {"--repetitions"});
  expect_usage_error("bench scale --min-seconds -1", {"--min-seconds"});
}

TEST(CliBench, MissingSceneFileIsNamed) {
  TempDir dir;
  expect_usage_error("bench paper --scene " + quoted(dir / "absent.json"), {"absent.json"});
}

}  // namespace
}  // namespace tailor::test

/// @file
/// `tailor simulate`: a short run, and its contract on bad input.

#include <fstream>

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliSimulate, Help) {
  expect_help("simulate", {"--scene", "--frames", "--out", "--method"});
}

TEST(CliSimulate, OneFrameOfASmallSleeve) {
  TempDir dir;
  const RunResult r =
      run_cli("simulate --frames 1 --rings 9 --segments 12 --out " + quoted(dir / "run"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, {"simulation summary", "frames"});
  EXPECT_TRUE(std::filesystem::exists(dir / "run" / "summary.json"));
}

TEST(CliSimulate, UnknownOptionAndBadValues) {
  expect_usage_error("simulate --no-such-option", {"--no-such-option"});
  expect_usage_error("simulate --frames -1", {"--frames"});
  expect_usage_error("simulate --frames 1 --gesture wave", {"wave"});
  expect_usage_error("simulate --frames 1 --method fastest", {"fastest"});
}

TEST(CliSimulate, BadSceneFilesAreNamed) {
  TempDir dir;
  expect_usage_error("simulate --scene " + quoted(dir / "absent.json"), {"absent.json"});
  { std::ofstream(dir / "broken.json") << "{ \"sleeve\": { \"rings\": "; }
  expect_usage_error("simulate --scene " + quoted(dir / "broken.json"), {"broken.json"});
  { std::ofstream(dir / "unknown.json") << "{ \"sleeve\": { \"colour\": \"red\" } }"; }
  expect_usage_error("simulate --scene " + quoted(dir / "unknown.json"),
                     {"unknown.json", "sleeve.colour"});
}

}  // namespace
}  // namespace tailor::test

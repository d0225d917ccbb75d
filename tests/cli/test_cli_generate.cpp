/// @file
/// `tailor generate`: a procedural step, and its contract on bad input.

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliGenerate, Help) {
  expect_help("generate", {"folded-cloth", "--triangles", "--out"});
}

TEST(CliGenerate, SmallFoldedCloth) {
  TempDir dir;
  const RunResult r =
      run_cli("generate folded-cloth --triangles 200 --out " + quoted(dir / "step"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "step" / "t0.ply"));
  EXPECT_TRUE(std::filesystem::exists(dir / "step" / "t1.ply"));
}

TEST(CliGenerate, UnknownOptionAndBadValues) {
  TempDir dir;
  const std::string out = " --out " + quoted(dir / "step");
  expect_usage_error("generate folded-cloth --no-such-option" + out, {"--no-such-option"});
  expect_usage_error("generate crumpled-paper" + out, {"crumpled-paper"});
  expect_usage_error("generate folded-cloth --triangles 10" + out, {"--triangles"});
  expect_usage_error("generate folded-cloth");  // --out is required
}

}  // namespace
}  // namespace tailor::test

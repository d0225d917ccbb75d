/// @file
/// The built `tailor info` command on good and bad input.

#include <gtest/gtest.h>

#include <string>

#include "io_test_support.hpp"

namespace tailor {
namespace {

using RunResult = test::CliResult;
using test::quoted;
using test::run_cli;

TEST(CliInfo, ReferenceMesh) {
  const auto path = std::filesystem::path(TAILOR_DATA_DIR) / "cloth-funnel/frames/227.ply";
  const RunResult r = run_cli("info " + quoted(path));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  test::expect_contains(r.output, {"vertices:", "9450", "faces:", "18484", "edges:",
                                   "boundary loops:", "components:", "manifold:", "bounding box"});
}

TEST(CliInfo, TruncatedFileExitsWithUsageError) {
  test::TempDir dir;
  const auto source = std::filesystem::path(TAILOR_DATA_DIR) / "thick-cloth/t0.ply";
  const std::string bytes = test::read_bytes(source);
  ASSERT_GT(bytes.size(), 1000u);
  test::write_bytes(dir / "cut.ply", bytes.substr(0, bytes.size() / 2));
  const RunResult r = run_cli("info " + quoted(dir / "cut.ply"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  test::expect_contains(r.output, {"cut.ply", "truncated"});
}

TEST(CliInfo, MissingFileAndBadOptions) {
  test::TempDir dir;
  const RunResult missing = run_cli("info " + quoted(dir / "absent.obj"));
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  test::expect_contains(missing.output, {"absent.obj", "cannot open"});
  const RunResult option = run_cli("info --no-such-option x.obj");
  EXPECT_EQ(option.exit_code, 2) << option.output;
  const RunResult no_argument = run_cli("info");
  EXPECT_EQ(no_argument.exit_code, 2) << no_argument.output;
}

}  // namespace
}  // namespace tailor

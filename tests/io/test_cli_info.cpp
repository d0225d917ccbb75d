/// @file
/// The built `tailor info` command on good and bad input.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "io_test_support.hpp"

namespace tailor {
namespace {

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

RunResult run_cli(const std::string& arguments) {
  const std::string command = std::string("'") + TAILOR_CLI_PATH + "' " + arguments + " 2>&1";
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  return result;
}

/// Single-quotes a path for the shell (appends piecewise: GCC 12 warns on "'" + string&&).
std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

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

/// @file
/// The `tailor` entry point: help, and no or unknown subcommand.

#include "cli_test_support.hpp"

namespace tailor::test {
namespace {

TEST(CliMain, HelpListsTheSubcommands) {
  const RunResult r = run_cli("--help");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, {"info", "detect", "ccd-check", "check-intersections", "simulate",
                             "generate", "bench"});
}

TEST(CliMain, NoOrUnknownSubcommandIsAUsageError) {
  expect_usage_error("", {"subcommand"});
  // CLI11 reports these as a missing subcommand / argument, without naming the token.
  expect_usage_error("teleport");
  expect_usage_error("--no-such-option info");
}

}  // namespace
}  // namespace tailor::test

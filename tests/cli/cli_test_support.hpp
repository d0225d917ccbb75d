#pragma once
/// @file
/// Running the built `tailor` CLI from a test: exit code and output.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/io_test_support.hpp"

namespace tailor::test {

/// What a CLI run gave (run_cli() and quoted() are in support/run_cli.hpp).
using RunResult = CliResult;

/// A file from the reference data (../shared/data).
inline std::filesystem::path data_file(const std::string& relative) {
  return std::filesystem::path(TAILOR_DATA_DIR) / relative;
}

/// Expects `tailor <arguments>` to fail with exit code 2 and an output containing `parts`.
inline void expect_usage_error(const std::string& arguments,
                               std::initializer_list<std::string_view> parts = {}) {
  const RunResult r = run_cli(arguments);
  EXPECT_EQ(r.exit_code, 2) << "tailor " << arguments << "\n" << r.output;
  expect_contains(r.output, parts);
}

/// Expects `tailor <subcommand> --help` to succeed and to list each of `options`.
inline void expect_help(const std::string& subcommand,
                        std::initializer_list<std::string_view> options) {
  const RunResult r = run_cli(subcommand + " --help");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_contains(r.output, options);
}

/// Writes the first half of a reference file: a truncated copy.
inline std::filesystem::path truncated_copy(const TempDir& dir, const std::string& relative,
                                            const std::string& name) {
  const std::string bytes = read_bytes(data_file(relative));
  EXPECT_GT(bytes.size(), 1000u);
  write_bytes(dir / name, bytes.substr(0, bytes.size() / 2));
  return dir / name;
}

}  // namespace tailor::test

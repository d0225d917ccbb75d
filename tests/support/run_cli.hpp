#pragma once
/// @file
/// Runs the built `tailor` executable (TAILOR_CLI_PATH) with arguments, for CLI tests.

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace tailor::testing {

/// Exit code and combined output of one run.
struct CliRun {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr
};

/// Runs `tailor <arguments>` through the shell (quote paths with quoted()).
inline CliRun run_cli(const std::string& arguments) {
  std::string command = "'";
  command += TAILOR_CLI_PATH;
  command += "' " + arguments + " 2>&1";
  CliRun result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  return result;
}

/// Single-quotes a path for the shell.
inline std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

}  // namespace tailor::testing

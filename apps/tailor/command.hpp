#pragma once
/// @file
/// Subcommand registry of the `tailor` CLI: each apps/tailor/cmd_*.cpp registers one
/// subcommand with a static CommandRegistration, so commands stay independent files.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace tailor::cli {

/// Exit codes shared by every command.
enum ExitCode : int {
  kSuccess = 0,
  kFailure = 1,     ///< the command ran and found a problem (e.g. a false negative)
  kUsageError = 2,  ///< bad options, missing or malformed input
};

/// Adds a subcommand to `app`; the returned callback runs it and gives the exit code.
using CommandSetup = std::function<std::function<int()>(CLI::App& app)>;

/// One registered subcommand.
struct CommandEntry {
  std::string name;
  CommandSetup setup;
};

/// All registered subcommands, in registration order.
std::vector<CommandEntry>& command_registry();

/// Registers a subcommand at static-initialisation time.
struct CommandRegistration {
  CommandRegistration(std::string name, CommandSetup setup);
};

}  // namespace tailor::cli

#pragma once
/// @file
/// Runs the built `tailor` executable (TAILOR_CLI_PATH) from tests: through the shell with
/// its output captured (run_cli), or without a shell, quietly, optionally interrupted
/// (run_cli_quietly).

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace tailor::testing {

/// Exit code and combined output of one run.
struct CliRun {
  int exit_code = -1;  ///< -1 when the process did not exit normally (e.g. a crash)
  std::string output;  ///< stdout and stderr
};

/// Runs `tailor ARGUMENTS` through the shell (arguments are shell words; quote paths with
/// quoted()). `shell_prefix` runs first in the same shell (e.g. `ulimit -v N;`).
inline CliRun run_cli(const std::string& arguments, const std::string& shell_prefix = "") {
  const std::string command =
      shell_prefix + " '" + std::string(TAILOR_CLI_PATH) + "' " + arguments + " 2>&1";
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

/// Single-quotes a path for the shell (appends piecewise: GCC 12 warns on "'" + string&&).
inline std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

/// Where run_cli_quietly() sends the CLI's stderr (its stdout always goes to /dev/null).
enum class Stderr { kKeep, kDiscard };

/// Runs `tailor ARGUMENTS...` without a shell, stdout to /dev/null, and waits for it. If
/// `interrupt_after` > 0, sends SIGINT after that many seconds. Returns the exit code,
/// 128 + the signal if a signal ended it, -1 if it could not be started.
inline int run_cli_quietly(const std::vector<std::string>& arguments, double interrupt_after = 0,
                           Stderr stderr_to = Stderr::kKeep) {
  std::vector<std::string> words{TAILOR_CLI_PATH};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (stderr_to == Stderr::kDiscard) {
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  if (interrupt_after > 0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(interrupt_after));
    kill(pid, SIGINT);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace tailor::testing

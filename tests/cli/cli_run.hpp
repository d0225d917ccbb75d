#pragma once
// Runs the built `tailor` executable from tests: to completion (exit code and output), or in
// the background (to signal it).

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace tailor::test {

/// Exit code and combined stdout + stderr of a finished run.
struct CliResult {
  int exit_code = -1;  ///< -1 if the process did not exit normally
  std::string output;
};

/// Runs `tailor ARGUMENTS` through the shell (so globs in ARGUMENTS expand) and waits.
inline CliResult run_cli(const std::string& arguments) {
  const std::string command = std::string("'") + TAILOR_CLI_PATH + "' " + arguments + " 2>&1";
  CliResult result;
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

/// Starts `tailor ARGUMENTS...` without a shell, stdout and stderr into `log`; returns its
/// pid (-1 if fork failed).
inline pid_t spawn_cli(const std::vector<std::string>& arguments,
                       const std::filesystem::path& log) {
  std::vector<std::string> words = {TAILOR_CLI_PATH};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string log_path = log.string();
  const pid_t pid = fork();
  if (pid == 0) {  // only async-signal-safe calls until exec
    const int fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

}  // namespace tailor::test

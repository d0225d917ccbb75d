#pragma once
/// @file
/// Runs the built `tailor` executable from tests in the background (to signal it); runs to
/// completion are support/run_cli.hpp's run_cli().

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/io_test_support.hpp"

namespace tailor::test {

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

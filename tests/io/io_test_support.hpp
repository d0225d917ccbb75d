#pragma once
/// @file
/// Helpers shared by the io tests: a per-test temporary folder and message checks.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>

#include "tailor/geometry/error.hpp"
#include "support/scoped_memory_budget.hpp"

namespace tailor::test {

/// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "-" + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';
    }
    m_path = std::filesystem::temp_directory_path() /
             ("tailor-io-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(m_path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return m_path; }
  std::filesystem::path operator/(const std::string& name) const { return m_path / name; }

 private:
  std::filesystem::path m_path;
};

/// Writes `bytes` to `path` as is.
inline void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(out.good()) << path;
}

/// Reads the whole file.
inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Runs `action`, which must throw InputError, and returns its message ("" if it did not).
inline std::string input_error_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return "";
}

/// Expects `message` to contain every one of `parts`.
inline void expect_contains(const std::string& message,
                            std::initializer_list<std::string_view> parts) {
  for (std::string_view part : parts) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "message \"" << message << "\" lacks \"" << part << "\"";
  }
}

/// Makes `path` a sparse file of `size` zero bytes (no disk blocks, no memory).
inline void make_sparse_file(const std::filesystem::path& path, std::uintmax_t size,
                             std::string_view head = {}) {
  write_bytes(path, head);
  std::filesystem::resize_file(path, size);
}

/// Exit code and combined output of one run of the built `tailor` CLI.
struct CliResult {
  int exit_code = -1;  ///< -1 when the process did not exit normally (e.g. a crash)
  std::string output;  ///< stdout and stderr
};

/// Runs `tailor ARGUMENTS` through the shell (arguments are shell words; quote paths with
/// quoted()). `shell_prefix` runs first in the same shell (e.g. `ulimit -v N;`).
inline CliResult run_cli(const std::string& arguments, const std::string& shell_prefix = "") {
  const std::string command =
      shell_prefix + " '" + std::string(TAILOR_CLI_PATH) + "' " + arguments + " 2>&1";
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

}  // namespace tailor::test

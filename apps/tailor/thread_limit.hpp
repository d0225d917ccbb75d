#pragma once
/// @file
/// The bound on `--threads`: a few times the hardware threads. TBB starts one OS thread
/// per requested worker; `--threads 100000` used to start 30,000 threads and stall the
/// machine (simulate) or crash in the task arena's shutdown (detect).

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>
#include <thread>

namespace tailor::cli {

/// Workers allowed per hardware thread (oversubscription beyond this only costs).
inline constexpr int kThreadsPerHardwareThread = 4;

/// The largest accepted `--threads`: 4 times the hardware threads (at least 4).
inline int max_threads() {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return kThreadsPerHardwareThread * hardware;
}

/// Validator for `--threads`: an integer in [0, max_threads()] (0 means all cores).
inline CLI::Validator thread_count_validator() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        long long n = 0;
        std::size_t used = 0;
        try {
          n = std::stoll(value, &used);
        } catch (const std::exception&) {
          return "must be an integer";
        }
        if (used != value.size()) return "must be an integer";
        if (n < 0 || n > max_threads()) {
          return "must be between 0 (all cores) and " + std::to_string(max_threads()) + " (" +
                 std::to_string(kThreadsPerHardwareThread) + " times the " +
                 std::to_string(max_threads() / kThreadsPerHardwareThread) + " hardware threads)";
        }
        return {};
      },
      "INT in [0, " + std::to_string(max_threads()) + "]", "THREADS");
}

}  // namespace tailor::cli

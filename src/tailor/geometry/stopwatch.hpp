#pragma once
/// @file
/// Wall-clock timing of pipeline stages (the per-stage times every module reports).

#include <chrono>

namespace tailor {

/// The clock of every stage time: monotonic, unaffected by changes of the system time.
using SteadyClock = std::chrono::steady_clock;

/// Milliseconds elapsed since `start`.
inline double milliseconds_since(SteadyClock::time_point start) {
  return std::chrono::duration<double, std::milli>(SteadyClock::now() - start).count();
}

}  // namespace tailor

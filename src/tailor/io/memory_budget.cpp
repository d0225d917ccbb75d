/// @file
/// The process-wide memory budget.

#include "tailor/io/memory_budget.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

std::atomic<std::uint64_t> g_budget{kDefaultMemoryBudget};

}  // namespace

std::uint64_t memory_budget() {
  return g_budget.load(std::memory_order_relaxed);
}

void set_memory_budget(std::uint64_t bytes) {
  g_budget.store(std::max<std::uint64_t>(bytes, 1), std::memory_order_relaxed);
}

std::string format_bytes(double bytes) {
  if (!std::isfinite(bytes)) return "an unbounded amount";
  if (bytes < 1024) return fmt::format("{:.0f} B", bytes);
  static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = bytes / 1024;
  std::size_t unit = 0;
  while (value >= 1024 && unit + 1 < std::size(kUnits)) {
    value /= 1024;
    ++unit;
  }
  return fmt::format("{:.1f} {}", value, kUnits[unit]);
}

void check_memory_budget(double bytes, const std::string& what) {
  const std::uint64_t budget = memory_budget();
  if (std::isfinite(bytes) && bytes <= static_cast<double>(budget)) return;
  throw InputError(
      fmt::format("{} needs about {}, more than the memory budget of {} (raise it with the "
                  "--max-memory option if the machine has the memory)",
                  what, format_bytes(bytes), format_bytes(static_cast<double>(budget))));
}

}  // namespace tailor

#pragma once
/// @file
/// The memory budget for anything sized by input: mesh files, query files, JSON files and
/// the scene's resolution. Code that allocates in proportion to a number it was given
/// estimates the bytes first and asks check_memory_budget(), so a hostile or careless
/// input is refused with a clear message instead of exhausting the machine.
///
/// The budget is process-wide: 4 GiB unless set_memory_budget() (the CLI's global
/// `--max-memory GIB` option) raises or lowers it.

#include <cstdint>
#include <string>

namespace tailor {

/// The default budget: 4 GiB.
inline constexpr std::uint64_t kDefaultMemoryBudget = std::uint64_t{4} << 30;

/// The current budget in bytes.
std::uint64_t memory_budget();

/// Sets the budget in bytes (0 is taken as 1 byte: everything sized is refused).
void set_memory_budget(std::uint64_t bytes);

/// Throws InputError "{what} needs about X (more than the memory budget of Y; ...)" when
/// `bytes` exceeds the budget. `bytes` is a double so that callers can multiply counts
/// without overflow; NaN and infinity are refused.
void check_memory_budget(double bytes, const std::string& what);

/// `bytes` as a short human-readable size ("512 B", "3.2 MiB", "4.0 GiB").
std::string format_bytes(double bytes);

}  // namespace tailor

/// @file
/// The memory budget: refusals name what was asked and how to raise the budget.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io_test_support.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {
namespace {

using test::expect_contains;
using test::input_error_message;

TEST(MemoryBudget, DefaultIsFourGiB) {
  EXPECT_EQ(memory_budget(), std::uint64_t{4} << 30);
}

TEST(MemoryBudget, AcceptsUpToTheBudgetAndRefusesAbove) {
  const test::ScopedMemoryBudget budget(1000);
  EXPECT_NO_THROW(check_memory_budget(1000, "a thing"));
  expect_contains(input_error_message([] { check_memory_budget(1001, "a big thing"); }),
                  {"a big thing", "needs about 1001 B", "memory budget of 1000 B", "--max-memory"});
  EXPECT_THROW(check_memory_budget(std::nan(""), "nan"), InputError);
  EXPECT_THROW(check_memory_budget(std::numeric_limits<double>::infinity(), "inf"), InputError);
}

TEST(MemoryBudget, SettingItRaisesTheLimit) {
  const test::ScopedMemoryBudget budget(std::uint64_t{64} << 30);
  EXPECT_NO_THROW(check_memory_budget(60.0 * (1 << 30), "a big machine's job"));
  set_memory_budget(0);  // taken as one byte: everything sized is refused
  EXPECT_EQ(memory_budget(), 1u);
  EXPECT_THROW(check_memory_budget(2, "two bytes"), InputError);
}

TEST(MemoryBudget, FormatsSizes) {
  EXPECT_EQ(format_bytes(512), "512 B");
  EXPECT_EQ(format_bytes(1536), "1.5 KiB");
  EXPECT_EQ(format_bytes(4.0 * (1 << 30)), "4.0 GiB");
  EXPECT_NE(format_bytes(1e30).find(" EiB"), std::string::npos) << format_bytes(1e30);
}

}  // namespace
}  // namespace tailor

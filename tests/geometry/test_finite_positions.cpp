// The first non-finite vertex of a position array, across many parallel blocks.

#include <gtest/gtest.h>

#include <limits>

#include "tailor/geometry/finite_positions.hpp"

namespace tailor {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Positions ramp(Index rows) {
  Positions x(rows, 3);
  for (Index i = 0; i < rows; ++i) x.row(i) = Vec3(i, -0.5 * i, 1e300);
  return x;
}

TEST(FinitePositions, FiniteArraysHaveNone) {
  EXPECT_FALSE(first_non_finite_vertex(Positions(0, 3)).has_value());
  EXPECT_FALSE(first_non_finite_vertex(ramp(1)).has_value());
  Positions x = ramp(100'000);
  x(7, 0) = std::numeric_limits<double>::max();
  x(8, 1) = -std::numeric_limits<double>::denorm_min();
  x(9, 2) = -0.0;
  EXPECT_FALSE(first_non_finite_vertex(x).has_value());
}

TEST(FinitePositions, EveryKindOfNonFiniteValueInEveryColumn) {
  for (const double bad : {kNaN, -kNaN, kInf, -kInf}) {
    for (Index column = 0; column < 3; ++column) {
      for (const Index row : {0, 1, 2729, 2730, 2731, 49'999}) {
        Positions x = ramp(50'000);
        x(row, column) = bad;
        const std::optional<Index> found = first_non_finite_vertex(x);
        ASSERT_TRUE(found.has_value()) << bad << " at " << row << "," << column;
        EXPECT_EQ(*found, row) << bad << " at " << row << "," << column;
      }
    }
  }
}

TEST(FinitePositions, TheLowestOfSeveralBadRowsInDifferentBlocks) {
  Positions x = ramp(200'000);
  for (const Index row : {199'999, 150'000, 90'001, 5'000, 5'001}) x(row, 1) = kNaN;
  x(70'000, 2) = kInf;
  EXPECT_EQ(first_non_finite_vertex(x), std::optional<Index>(5'000));
  x(4'999, 0) = -kInf;
  EXPECT_EQ(first_non_finite_vertex(x), std::optional<Index>(4'999));
}

}  // namespace
}  // namespace tailor

/// @file
/// The pinned set: ids sorted and unique, flags, rest rows in id order, infinite masses,
/// and an id out of range refused.

#include <gtest/gtest.h>

#include <cmath>

#include "tailor/geometry/error.hpp"
#include "tailor/sim/pinned_vertices.hpp"

namespace tailor {
namespace {

TEST(PinnedVertices, EveryFormAgrees) {
  Positions rest(5, 3);
  for (int i = 0; i < 5; ++i) rest.row(i) << i, 10 * i, 100 * i;
  const PinnedVertices pinned({3, 1, 3}, rest);
  EXPECT_EQ(pinned.ids(), (std::vector<Index>{1, 3}));
  EXPECT_EQ(pinned.flags(), (std::vector<char>{0, 1, 0, 1, 0}));
  ASSERT_EQ(pinned.rest().rows(), 2);
  EXPECT_EQ(pinned.rest().row(1), rest.row(3));
  const Eigen::VectorXd masses = pinned.with_infinite_masses(Eigen::VectorXd::Ones(5));
  EXPECT_TRUE(std::isinf(masses[1]) && std::isinf(masses[3]));
  EXPECT_EQ(masses[0] + masses[2] + masses[4], 3.0);
  EXPECT_THROW(PinnedVertices({5}, rest), InputError);
}

}  // namespace
}  // namespace tailor

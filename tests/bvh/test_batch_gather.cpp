// Batch gathers: the four-lane gather (masked loads, transposed in registers) fills every
// row and lane exactly as add() and pad() do, including padding lanes and the last vertex
// of the position array (whose fourth double is past the end and must not be read).

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "tailor/bvh/batch_gather.hpp"

namespace tailor {
namespace {

TEST(BatchGather, FourLanesEqualAddingOneByOneAndPadding) {
  if (!detail::direction_mask_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor";
  std::mt19937_64 rng(3);
  const Index vertices = 50;
  // Exactly 3 doubles per vertex: the last vertex's masked load ends the array.
  std::vector<double> x0(3 * vertices), x1(3 * vertices);
  std::uniform_real_distribution<double> uniform(-1e3, 1e3);
  for (double& c : x0) c = uniform(rng);
  for (double& c : x1) c = uniform(rng);
  std::uniform_int_distribution<Index> vertex(0, vertices - 1);
  for (int count = 1; count <= MovingTriangleBatch::kCapacity; ++count) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::array<Index, 3>> faces(static_cast<std::size_t>(count));
      for (auto& f : faces) f = {vertex(rng), vertex(rng), vertices - 1};
      MovingTriangleBatch one, four;
      detail::gather_batch_one_by_one(x0.data(), x1.data(), faces, one);
      detail::gather_batch_four_lanes(x0.data(), x1.data(), faces, four);
      ASSERT_EQ(one.count, count);
      ASSERT_EQ(four.count, count);
      ASSERT_EQ(four.padded_count(), (count + 3) / 4 * 4);
      for (int row = 0; row < 18; ++row) {
        for (int lane = 0; lane < one.padded_count(); ++lane) {
          ASSERT_EQ(one.coordinate[row][lane], four.coordinate[row][lane])
              << "count " << count << " row " << row << " lane " << lane;
        }
      }
    }
  }
}

TEST(BatchGather, RowsHoldTheCornersInOrder) {
  // Corner k ∈ {a, b, c} at frame s, coordinate j is row (3·s + k)·3 + j.
  const std::vector<double> x0{0, 1, 2, 10, 11, 12, 20, 21, 22};
  const std::vector<double> x1{100, 101, 102, 110, 111, 112, 120, 121, 122};
  const std::vector<std::array<Index, 3>> faces{{2, 0, 1}};
  MovingTriangleBatch batch;
  gather_batch(x0.data(), x1.data(), faces, batch);
  EXPECT_EQ(batch.coordinate[0][0], 20);    // a0.x
  EXPECT_EQ(batch.coordinate[4][0], 1);     // b0.y
  EXPECT_EQ(batch.coordinate[8][0], 12);    // c0.z
  EXPECT_EQ(batch.coordinate[9][0], 120);   // a1.x
  EXPECT_EQ(batch.coordinate[17][0], 112);  // c1.z
  EXPECT_EQ(batch.coordinate[17][3], 112);  // padding repeats lane 0
}

}  // namespace
}  // namespace tailor

// The boxes of a group's nodes: on random pre-order trees of 1-16 leaves, every leaf gets
// its lane's bounds and every inner node the union of its children's, computed here by
// recursion over the tree; the SSE2 and AVX2 paths write the same boxes and leave the rest
// of each record as it was. A group may start at any lane of the batch (a batch holds
// several small groups).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <random>
#include <vector>

#include "tailor/bvh/group_boxes.hpp"

namespace tailor {
namespace {

// A node record as the MeshBvh keeps it: a box and eight more bytes.
struct Record {
  FloatBox box;
  std::int32_t rest[2];
};

constexpr std::int32_t kUntouched = 0x5eed;

struct Tree {
  std::uint32_t leaf_bits = 0;
  std::vector<FloatBox> expected;  // per node
};

// Appends a random subtree of `leaves` leaves in pre-order; the leaves take lanes
// `lane`, `lane` + 1, ... Returns the subtree's box.
FloatBox grow(std::mt19937_64& rng, int leaves, int& lane, const BatchBounds& bounds, Tree& tree) {
  const int node = static_cast<int>(tree.expected.size());
  tree.expected.emplace_back();
  FloatBox box;
  if (leaves == 1) {
    tree.leaf_bits |= std::uint32_t{1} << node;
    for (int k = 0; k < 3; ++k) box.min[k] = bounds.low[k][lane], box.max[k] = bounds.high[k][lane];
    ++lane;
  } else {
    const int left = std::uniform_int_distribution<int>(1, leaves - 1)(rng);
    box = grow(rng, left, lane, bounds, tree);
    box.extend(grow(rng, leaves - left, lane, bounds, tree));
  }
  tree.expected[static_cast<std::size_t>(node)] = box;
  return box;
}

TEST(GroupBoxes, EveryNodeIsItsLeafOrTheUnionOfItsChildren) {
  const bool avx2 = detail::direction_mask_has_avx2();
  if (!avx2) std::cout << "no AVX2 on this processor: the AVX2 path is not compared\n";
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<float> uniform(-100, 100);
  std::uniform_int_distribution<int> count_of(1, MovingTriangleBatch::kCapacity);
  for (int trial = 0; trial < 2000; ++trial) {
    BatchBounds bounds;
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < MovingTriangleBatch::kCapacity; ++i) {
        const float a = uniform(rng), b = uniform(rng);
        bounds.low[k][i] = std::min(a, b), bounds.high[k][i] = std::max(a, b);
      }
    }
    const int count = count_of(rng);
    const int first_lane =
        std::uniform_int_distribution<int>(0, MovingTriangleBatch::kCapacity - count)(rng);
    Tree tree;
    int lane = first_lane;
    grow(rng, count, lane, bounds, tree);
    ASSERT_EQ(static_cast<int>(tree.expected.size()), 2 * count - 1);

    for (const bool use_avx2 : {false, true}) {
      if (use_avx2 && !avx2) continue;
      std::vector<Record> records(tree.expected.size() + 1);
      for (Record& r : records) r.rest[0] = r.rest[1] = kUntouched;
      (use_avx2 ? detail::write_group_boxes_avx2 : detail::write_group_boxes_sse2)(
          bounds, first_lane, tree.leaf_bits, count, &records[0].box, sizeof(Record));
      for (std::size_t node = 0; node < tree.expected.size(); ++node) {
        ASSERT_EQ(records[node].box.min, tree.expected[node].min)
            << "trial " << trial << " node " << node << (use_avx2 ? " (AVX2)" : "");
        ASSERT_EQ(records[node].box.max, tree.expected[node].max)
            << "trial " << trial << " node " << node << (use_avx2 ? " (AVX2)" : "");
        ASSERT_EQ(records[node].rest[0], kUntouched);
        ASSERT_EQ(records[node].rest[1], kUntouched);
      }
      // The record after the group is not written.
      EXPECT_EQ(records.back().box.min[0], FloatBox{}.min[0]);
    }
  }
}

}  // namespace
}  // namespace tailor

// The boxes of a group's nodes: on random pre-order trees of 1-16 leaves, every leaf gets
// its lane's bounds and every inner node the union of its children's, computed here by
// recursion over the tree; the SSE2 and AVX2 paths write the same boxes and leave the rest
// of each record as it was. A group may start at any lane of the batch (a batch holds
// several small groups). The same for the diagonal boxes (four directions, 32 bytes).

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

// A diagonal box and the record after it.
struct DiagonalRecord {
  DiagonalBox box;
  std::int32_t rest[2];
};

constexpr std::int32_t kUntouched = 0x5eed;

template <class Box>
struct Tree {
  std::uint32_t leaf_bits = 0;
  std::vector<Box> expected;  // per node
};

// Appends a random subtree of `leaves` leaves in pre-order; the leaves take lanes
// `lane`, `lane` + 1, ... Returns the subtree's box.
template <class Box, class Bounds>
Box grow(std::mt19937_64& rng, int leaves, int& lane, const Bounds& bounds, Tree<Box>& tree) {
  const int node = static_cast<int>(tree.expected.size());
  tree.expected.emplace_back();
  Box box;
  if (leaves == 1) {
    tree.leaf_bits |= std::uint32_t{1} << node;
    for (std::size_t k = 0; k < box.min.size(); ++k) {
      box.min[k] = bounds.low[k][lane], box.max[k] = bounds.high[k][lane];
    }
    ++lane;
  } else {
    const int left = std::uniform_int_distribution<int>(1, leaves - 1)(rng);
    box = grow(rng, left, lane, bounds, tree);
    const Box right = grow(rng, leaves - left, lane, bounds, tree);
    for (std::size_t k = 0; k < box.min.size(); ++k) {
      box.min[k] = std::min(box.min[k], right.min[k]);
      box.max[k] = std::max(box.max[k], right.max[k]);
    }
  }
  tree.expected[static_cast<std::size_t>(node)] = box;
  return box;
}

// Random bounds for every lane and direction of `bounds`.
template <class Bounds>
void fill(std::mt19937_64& rng, Bounds& bounds) {
  std::uniform_real_distribution<float> uniform(-100, 100);
  for (auto k = 0u; k < std::size(bounds.low); ++k) {
    for (int i = 0; i < MovingTriangleBatch::kCapacity; ++i) {
      const float a = uniform(rng), b = uniform(rng);
      bounds.low[k][i] = std::min(a, b), bounds.high[k][i] = std::max(a, b);
    }
  }
}

// Runs `trials` random groups through `write` (each path of a writer) into records of type
// RecordT and checks every node's box and the untouched rest.
template <class Box, class Bounds, class RecordT, class Write>
void check_writer(Write write, bool avx2_available) {
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> count_of(1, MovingTriangleBatch::kCapacity);
  for (int trial = 0; trial < 2000; ++trial) {
    Bounds bounds;
    fill(rng, bounds);
    const int count = count_of(rng);
    const int first_lane =
        std::uniform_int_distribution<int>(0, MovingTriangleBatch::kCapacity - count)(rng);
    Tree<Box> tree;
    int lane = first_lane;
    grow(rng, count, lane, bounds, tree);
    ASSERT_EQ(static_cast<int>(tree.expected.size()), 2 * count - 1);
    for (const bool use_avx2 : {false, true}) {
      if (use_avx2 && !avx2_available) continue;
      std::vector<RecordT> records(tree.expected.size() + 1);
      for (RecordT& r : records) r.rest[0] = r.rest[1] = kUntouched;
      const Box initial = records.back().box;
      write(use_avx2, bounds, first_lane, tree.leaf_bits, count, &records[0].box, sizeof(RecordT));
      for (std::size_t node = 0; node < tree.expected.size(); ++node) {
        ASSERT_EQ(records[node].box.min, tree.expected[node].min)
            << "trial " << trial << " node " << node << (use_avx2 ? " (AVX2)" : "");
        ASSERT_EQ(records[node].box.max, tree.expected[node].max)
            << "trial " << trial << " node " << node << (use_avx2 ? " (AVX2)" : "");
        ASSERT_EQ(records[node].rest[0], kUntouched);
        ASSERT_EQ(records[node].rest[1], kUntouched);
      }
      // The record after the group is not written.
      EXPECT_EQ(records.back().box.min, initial.min);
    }
  }
}

TEST(GroupBoxes, EveryNodeIsItsLeafOrTheUnionOfItsChildren) {
  const bool avx2 = detail::direction_mask_has_avx2();
  if (!avx2) std::cout << "no AVX2 on this processor: the AVX2 path is not compared\n";
  check_writer<FloatBox, BatchBounds, Record>(
      [](bool use_avx2, auto&&... args) {
        (use_avx2 ? detail::write_group_boxes_avx2 : detail::write_group_boxes_sse2)(args...);
      },
      avx2);
}

TEST(GroupBoxes, EveryDiagonalBoxIsItsLeafOrTheUnionOfItsChildren) {
  check_writer<DiagonalBox, DiagonalBatchBounds, DiagonalRecord>(
      [](bool use_avx2, auto&&... args) {
        (use_avx2 ? detail::write_group_diagonal_boxes_avx2
                  : detail::write_group_diagonal_boxes_sse2)(args...);
      },
      detail::direction_mask_has_avx2());
}

}  // namespace
}  // namespace tailor

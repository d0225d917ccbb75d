// BasicBvh's walks against every pair: the pairs of two trees and of one tree with itself,
// sequential and parallel, equal the pairs brute force finds, for boxes at one instant (Aabb)
// and boxes at both ends of a step (StepBox, whose walks end in buckets compared sixteen or
// eight boxes at a time by StepBoxColumns); and StepBoxColumns gives back each box, and its
// mask (the SSE and the AVX-512 kernel) equals may_meet_over_step() lane by lane, for every
// count of boxes, with the lanes past the count holding boxes that would meet.

#include <gtest/gtest.h>

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "tailor/bvh/bvh.hpp"

namespace tailor {
namespace {

using Pairs = std::vector<std::pair<Index, Index>>;

// Clustered boxes of mixed sizes: some overlap many, some none (a bucket then holds both).
Aabb random_aabb(std::mt19937& rng) {
  std::uniform_real_distribution<double> cluster(0.0, 4.0), offset(-0.3, 0.3), size(0.0, 0.25);
  const Eigen::Array3d center(std::floor(cluster(rng)) + offset(rng),
                              std::floor(cluster(rng)) + offset(rng), offset(rng));
  const Eigen::Array3d half(size(rng), size(rng), size(rng));
  return Aabb{center - half, center + half};
}

StepBox random_step_box(std::mt19937& rng) {
  // The end box moves by up to the box size, so the two ends' order along an axis varies.
  const Aabb start = random_aabb(rng);
  std::uniform_real_distribution<double> shift(-0.4, 0.4);
  const Eigen::Array3d by(shift(rng), shift(rng), shift(rng));
  return StepBox::holding(start, Aabb{start.min + by, start.max + by});
}

template <class Box>
std::vector<Box> random_boxes(std::mt19937& rng, int n) {
  std::vector<Box> boxes;
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<Box, StepBox>) {
      boxes.push_back(random_step_box(rng));
    } else {
      boxes.push_back(random_aabb(rng));
    }
  }
  return boxes;
}

Pairs sorted(Pairs pairs) {
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

template <class Box>
Pairs parallel_pairs(const BasicBvh<Box>& a, const BasicBvh<Box>* b) {
  tbb::enumerable_thread_specific<Pairs> found;
  const auto local = [&]() -> Pairs& { return found.local(); };
  const auto visit = [](Pairs& sink, Index p, Index q) { sink.emplace_back(p, q); };
  if (b != nullptr) {
    a.parallel_for_each_overlapping_pair(*b, local, visit);
  } else {
    a.parallel_for_each_self_overlapping_pair(local, visit);
  }
  Pairs all;
  for (const Pairs& part : found) all.insert(all.end(), part.begin(), part.end());
  return all;
}

template <class Box>
void expect_walks_find_every_overlapping_pair(unsigned seed) {
  std::mt19937 rng(seed);
  for (const int n : {1, 2, 7, 8, 9, 17, 300, 5000}) {
    const std::vector<Box> a = random_boxes<Box>(rng, n), b = random_boxes<Box>(rng, n / 2 + 3);
    Pairs expected_pairs, expected_self;
    for (Index p = 0; p < n; ++p) {
      for (Index q = 0; q < static_cast<Index>(b.size()); ++q) {
        if (a[p].overlaps(b[q])) expected_pairs.emplace_back(p, q);
      }
      for (Index q = p + 1; q < n; ++q) {
        if (a[p].overlaps(a[q])) expected_self.emplace_back(p, q);
      }
    }
    const BasicBvh<Box> tree_a(a), tree_b(b);
    Pairs pairs, self;
    tree_a.for_each_overlapping_pair(tree_b, [&](Index p, Index q) { pairs.emplace_back(p, q); });
    tree_a.for_each_self_overlapping_pair(
        [&](Index p, Index q) { self.emplace_back(std::min(p, q), std::max(p, q)); });
    Pairs parallel_self = parallel_pairs(tree_a, static_cast<const BasicBvh<Box>*>(nullptr));
    for (auto& [p, q] : parallel_self) std::tie(p, q) = std::pair{std::min(p, q), std::max(p, q)};
    EXPECT_EQ(sorted(pairs), expected_pairs) << n << " boxes";
    EXPECT_EQ(sorted(self), expected_self) << n << " boxes";
    EXPECT_EQ(sorted(parallel_pairs(tree_a, &tree_b)), expected_pairs) << n << " boxes";
    EXPECT_EQ(sorted(parallel_self), expected_self) << n << " boxes";
    // Some pairs, not all: the walks have something to find and something to skip.
    EXPECT_LT(expected_self.size(), static_cast<std::size_t>(n) * (n - 1) / 2 + (n < 10));
  }
}

TEST(Bvh, WalksOfBoxesAtOneInstantFindEveryOverlappingPair) {
  expect_walks_find_every_overlapping_pair<Aabb>(11);
}

TEST(Bvh, WalksOfBoxesAtBothEndsFindEveryPairThatMayMeet) {
  expect_walks_find_every_overlapping_pair<StepBox>(12);
}

TEST(StepBoxColumns, MaskIsMayMeetOverStepForEachLane) {
  std::mt19937 rng(13);
  const int n = 64;
  std::vector<StepBox> boxes = random_boxes<StepBox>(rng, n);
  StepBoxColumns columns;
  columns.resize(n);
  for (Index i = 0; i < n; ++i) columns.set(i, boxes[i]);
  for (Index i = 0; i < n; ++i) {
    const StepBox back = columns.box(i);
    EXPECT_TRUE(back.start.min == boxes[i].start.min && back.start.max == boxes[i].start.max &&
                back.end.min == boxes[i].end.min && back.end.max == boxes[i].end.max);
  }
  // The kernel this processor runs, the SSE one, and the AVX-512 one where it runs.
  std::vector<std::function<std::uint32_t(const StepBox&, Index, int)>> kernels = {
      [&](const StepBox& box, Index first, int count) {
        return columns.may_meet_mask(box, first, count);
      },
      [&](const StepBox& box, Index first, int count) {
        return detail::may_meet_mask_sse(columns.columns(), box, first, count);
      }};
  if (__builtin_cpu_supports("avx512f")) {
    kernels.push_back([&](const StepBox& box, Index first, int count) {
      return detail::may_meet_mask_avx512(columns.columns(), box, first, count);
    });
  }
  int met = 0, apart = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const StepBox box = random_step_box(rng);
    for (int count = 0; count <= StepBoxColumns::kLanes; ++count) {
      const Index first = trial % (n - StepBoxColumns::kLanes);
      for (std::size_t kernel = 0; kernel < kernels.size(); ++kernel) {
        if (kernel == 0 && count > StepBoxColumns::lanes()) continue;
        const std::uint32_t mask = kernels[kernel](box, first, count);
        for (int j = 0; j < 32; ++j) {
          const bool expected = j < count && box.overlaps(boxes[first + j]);
          EXPECT_EQ((mask >> j) & 1u, expected ? 1u : 0u)
              << "kernel " << kernel << " lane " << j << " of " << count;
          if (j < count) (expected ? met : apart) += 1;
        }
      }
    }
  }
  EXPECT_GT(met, 100);
  EXPECT_GT(apart, 100);
  // A box that meets every stored one still sets no bit past the count.
  StepBox everywhere;
  everywhere.start.min = everywhere.end.min = {-1e30f, -1e30f, -1e30f};
  everywhere.start.max = everywhere.end.max = {1e30f, 1e30f, 1e30f};
  EXPECT_EQ(columns.may_meet_mask(everywhere, 0, 3), 0b111u);
  EXPECT_EQ(columns.may_meet_mask(everywhere, n - 1, 1), 0b1u);
}

}  // namespace
}  // namespace tailor

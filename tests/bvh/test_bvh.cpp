// BasicBvh's walks against every pair: the pairs of two trees and of one tree with itself,
// sequential and parallel, equal the pairs brute force finds, for boxes at one instant (Aabb)
// and boxes at both ends of a step (StepBox, whose walks end in buckets compared sixteen or
// eight boxes at a time by StepBoundColumns); and StepBoundColumns gives back each set's
// bounds, and its mask (the SSE and the AVX-512 kernel) equals may_meet_over_step() along the
// axes, and the diagonals when used, lane by lane, for every count of sets, with the lanes
// past the count holding sets that would meet.

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

// A set's bounds along the axes (a StepBox) and along the diagonals: the slabs of its boxes
// along each diagonal, narrowed at each end by up to 30 % (as a triangle's slabs are narrower
// than its box's), so that the diagonals part some sets whose boxes meet.
struct SetBox {
  StepBox axes;
  DiagonalBox diagonal_start, diagonal_end;
};

DiagonalBox narrowed_slabs(const FloatBox& box, std::mt19937& rng) {
  constexpr int kSign[kDiagonals][3] = {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
  std::uniform_real_distribution<float> narrow(0.0f, 0.3f);
  DiagonalBox slabs;
  for (int k = 0; k < kDiagonals; ++k) {
    float low = 0.0f, high = 0.0f;
    for (int i = 0; i < 3; ++i) {
      low += kSign[k][i] > 0 ? box.min[i] : -box.max[i];
      high += kSign[k][i] > 0 ? box.max[i] : -box.min[i];
    }
    const float width = high - low;
    slabs.min[k] = low + narrow(rng) * width;
    slabs.max[k] = high - narrow(rng) * width;
  }
  return slabs;
}

SetBox random_set_box(std::mt19937& rng) {
  SetBox set{random_step_box(rng), {}, {}};
  set.diagonal_start = narrowed_slabs(set.axes.start, rng);
  set.diagonal_end = narrowed_slabs(set.axes.end, rng);
  return set;
}

// The definition the kernels must follow: may_meet_over_step() along the axes, and along the
// diagonals when they are used.
bool may_meet(const SetBox& a, const SetBox& b, int directions) {
  return a.axes.overlaps(b.axes) &&
         (directions == 3 ||
          may_meet_over_step(a.diagonal_start, a.diagonal_end, b.diagonal_start, b.diagonal_end));
}

void store(StepBoundColumns& columns, Index i, const SetBox& set) {
  columns.set(i, set.axes);
  if (columns.directions() == 3) return;
  for (int k = 0; k < kDiagonals; ++k) {
    columns.column(3 + k, StepBoundColumns::kStartMin)[i] = set.diagonal_start.min[k];
    columns.column(3 + k, StepBoundColumns::kStartMax)[i] = set.diagonal_start.max[k];
    columns.column(3 + k, StepBoundColumns::kEndMin)[i] = set.diagonal_end.min[k];
    columns.column(3 + k, StepBoundColumns::kEndMax)[i] = set.diagonal_end.max[k];
  }
}

// masks[r] for rows [first_row, first_row + rows) of `row_sets` against sets [first, first +
// count) of `columns`, one per kernel: the one this processor runs (count ≤ lanes()), the SSE
// one, and the AVX-512 one where it runs.
using MaskKernel = std::function<void(const StepBoundColumns& rows, Index first_row, int row_count,
                                      const StepBoundColumns& columns, int directions, Index first,
                                      int count, std::uint32_t* masks)>;

StepBoundColumns::View view_of(const StepBoundColumns& columns, Index first) {
  const float* data = columns.column(0, StepBoundColumns::kStartMin);
  return {data + first,
          static_cast<std::size_t>(columns.column(0, StepBoundColumns::kStartMax) - data)};
}

std::vector<MaskKernel> mask_kernels() {
  std::vector<MaskKernel> kernels = {
      [](const StepBoundColumns& rows, Index first_row, int row_count,
         const StepBoundColumns& columns, int directions, Index first, int count,
         std::uint32_t* masks) {
        columns.may_meet_masks(rows, {first_row, row_count}, {first, count}, directions, masks);
      },
      [](const StepBoundColumns& rows, Index first_row, int row_count,
         const StepBoundColumns& columns, int directions, Index first, int count,
         std::uint32_t* masks) {
        detail::may_meet_masks_sse(view_of(rows, first_row), view_of(columns, first), row_count,
                                   directions, count, masks);
      }};
  if (__builtin_cpu_supports("avx512f")) {
    kernels.push_back([](const StepBoundColumns& rows, Index first_row, int row_count,
                         const StepBoundColumns& columns, int directions, Index first, int count,
                         std::uint32_t* masks) {
      detail::may_meet_masks_avx512(view_of(rows, first_row), view_of(columns, first), row_count,
                                    directions, count, masks);
    });
  }
  return kernels;
}

StepBoundColumns stored_columns(const std::vector<SetBox>& sets, int directions) {
  StepBoundColumns columns;
  columns.resize(directions, static_cast<Index>(sets.size()));
  for (Index i = 0; i < static_cast<Index>(sets.size()); ++i) store(columns, i, sets[i]);
  return columns;
}

TEST(StepBoundColumns, MasksAreMayMeetOverStepForEachLane) {
  std::mt19937 rng(13);
  const int n = 64;
  const std::vector<MaskKernel> kernels = mask_kernels();
  for (const int stored : {3, StepBoundColumns::kMaxDirections}) {
    std::vector<SetBox> sets, row_sets;
    for (int i = 0; i < n; ++i) sets.push_back(random_set_box(rng));
    for (int i = 0; i < n; ++i) row_sets.push_back(random_set_box(rng));
    const StepBoundColumns columns = stored_columns(sets, stored);
    const StepBoundColumns rows = stored_columns(row_sets, stored);
    for (Index i = 0; i < n; ++i) {
      const StepBox back = columns.box(i);
      const StepBox& box = sets[i].axes;
      EXPECT_TRUE(back.start.min == box.start.min && back.start.max == box.start.max &&
                  back.end.min == box.end.min && back.end.max == box.end.max);
    }
    // With the diagonals stored, a query may still use the axes alone (MeshBvh refitted
    // without them).
    for (const int directions : {3, stored}) {
      int met = 0, apart = 0, parted_by_diagonals = 0;
      for (int trial = 0; trial < 60; ++trial) {
        const Index first = trial % (n - StepBoundColumns::kLanes);
        const Index first_row = (7 * trial) % (n - StepBoundColumns::kLanes);
        const int row_count = 1 + trial % StepBoundColumns::kLanes;
        for (int count = 0; count <= StepBoundColumns::kLanes; ++count) {
          for (std::size_t kernel = 0; kernel < kernels.size(); ++kernel) {
            if (kernel == 0 && count > StepBoundColumns::lanes()) continue;
            std::uint32_t masks[StepBoundColumns::kLanes];
            kernels[kernel](rows, first_row, row_count, columns, directions, first, count, masks);
            for (int r = 0; r < row_count; ++r) {
              for (int j = 0; j < 32; ++j) {
                const bool expected =
                    j < count && may_meet(row_sets[first_row + r], sets[first + j], directions);
                EXPECT_EQ((masks[r] >> j) & 1u, expected ? 1u : 0u)
                    << "kernel " << kernel << " row " << r << " lane " << j << " of " << count
                    << ", " << directions << " directions";
                if (j < count) (expected ? met : apart) += 1;
                parted_by_diagonals += j < count && !expected &&
                                       row_sets[first_row + r].axes.overlaps(sets[first + j].axes);
              }
            }
          }
        }
      }
      EXPECT_GT(met, 100);
      EXPECT_GT(apart, 100);
      if (directions > 3) {
        EXPECT_GT(parted_by_diagonals, 100);
      }
    }
    // Within one range: only the sets after each row, and each pair that may meet.
    std::uint32_t masks[StepBoundColumns::kLanes];
    columns.may_meet_masks_within({5, StepBoundColumns::lanes()}, stored, masks);
    for (int r = 0; r < StepBoundColumns::lanes(); ++r) {
      for (int j = 0; j < 32; ++j) {
        const bool expected =
            j > r && j < StepBoundColumns::lanes() && may_meet(sets[5 + r], sets[5 + j], stored);
        EXPECT_EQ((masks[r] >> j) & 1u, expected ? 1u : 0u) << "row " << r << " lane " << j;
      }
    }
    // A set that meets every stored one still sets no bit past the count.
    SetBox everywhere;
    everywhere.axes.start.min = everywhere.axes.end.min = {-1e30f, -1e30f, -1e30f};
    everywhere.axes.start.max = everywhere.axes.end.max = {1e30f, 1e30f, 1e30f};
    everywhere.diagonal_start.min.fill(-1e30f);
    everywhere.diagonal_end.min.fill(-1e30f);
    everywhere.diagonal_start.max.fill(1e30f);
    everywhere.diagonal_end.max.fill(1e30f);
    const StepBoundColumns wide = stored_columns({everywhere}, stored);
    columns.may_meet_masks(wide, {0, 1}, {0, 3}, stored, masks);
    EXPECT_EQ(masks[0], 0b111u);
    columns.may_meet_masks(wide, {0, 1}, {n - 1, 1}, stored, masks);
    EXPECT_EQ(masks[0], 0b1u);
  }
}

}  // namespace
}  // namespace tailor

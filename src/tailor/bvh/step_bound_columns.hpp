#pragma once
/// @file
/// Bounds of sets moving over a step, in structure-of-arrays form, so that one set is
/// compared with sixteen at once (AVX-512; eight elsewhere): the buckets at the bottom of the
/// tree walks, where one node pair used to be visited per pair of leaves. BasicBvh<StepBox>
/// (the candidate walk of collisions with a thickness) keeps the three axes; MeshBvh keeps
/// the axes and the four diagonals of diagonal_bounds.hpp for its leaves.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tailor/bvh/diagonal_bounds.hpp"
#include "tailor/bvh/step_boxes.hpp"
#include "tailor/bvh/unwritten_allocator.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor {

/// Per set and fixed direction (the axes x, y, z, then the diagonals d0 to d3), four bounds:
/// the set's minimum and maximum along it at t = 0 and at t = 1, one float column each,
/// padded by kLanes entries so that any kLanes consecutive sets load.
class StepBoundColumns {
 public:
  /// Most sets compared at once.
  static constexpr int kLanes = 16;
  /// The axes and the diagonals.
  static constexpr int kMaxDirections = 3 + kDiagonals;
  /// The four bounds of a set along a direction, in the order of their columns.
  enum Bound : int {
    kStartMin = 0,  ///< minimum at t = 0
    kStartMax = 1,  ///< maximum at t = 0
    kEndMin = 2,    ///< minimum at t = 1
    kEndMax = 3,    ///< maximum at t = 1
  };

  /// Sets this processor compares at once: 16 with AVX-512, 8 otherwise (two SSE vectors;
  /// sixteen in four were no faster than eight in two).
  static int lanes();

  /// Room for `n` sets along the first `directions` directions. Their bounds are left
  /// unwritten (the owners write every set's before a mask reads it, in parallel, so no page
  /// is zeroed on one thread first); the padding is zero.
  void resize(int directions, Index n) {
    m_directions = directions;
    m_stride = static_cast<std::size_t>(n) + kLanes;
    m_data.resize(4 * static_cast<std::size_t>(directions) * m_stride);
    for (int c = 0; c < 4 * directions; ++c) {
      std::fill_n(m_data.data() + c * m_stride + n, kLanes, 0.0f);
    }
  }
  /// Directions stored.
  int directions() const { return m_directions; }
  /// The column of `bound` along direction `k` (set i at entry i).
  float* column(int k, Bound bound) { return m_data.data() + offset(k, bound); }
  /// The same, read only.
  const float* column(int k, Bound bound) const { return m_data.data() + offset(k, bound); }

  /// Stores the axes' bounds of set `i`.
  void set(Index i, const StepBox& box) {
    for (int k = 0; k < 3; ++k) {
      column(k, kStartMin)[i] = box.start.min[k];
      column(k, kStartMax)[i] = box.start.max[k];
      column(k, kEndMin)[i] = box.end.min[k];
      column(k, kEndMax)[i] = box.end.max[k];
    }
  }
  /// The axes' bounds of set `i` as a box.
  StepBox box(Index i) const {
    StepBox box;
    for (int k = 0; k < 3; ++k) {
      box.start.min[k] = column(k, kStartMin)[i];
      box.start.max[k] = column(k, kStartMax)[i];
      box.end.min[k] = column(k, kEndMin)[i];
      box.end.max[k] = column(k, kEndMax)[i];
    }
    return box;
  }

  /// A range of stored sets: `count` sets from `first`.
  struct Sets {
    Index first;  ///< the first set
    int count;    ///< how many
  };
  /// For each set row_sets.first + r in `rows` (at most 32), masks[r]: bit j (j <
  /// sets.count ≤ lanes()) set when that set and this object's set sets.first + j may meet
  /// over the step: along none of the first `directions` directions (≤ both objects'
  /// directions()) are they apart at both ends in one order (may_meet_over_step() per
  /// direction), lanes() sets at a time.
  void may_meet_masks(const StepBoundColumns& rows, Sets row_sets, Sets sets, int directions,
                      std::uint32_t* masks) const {
    s_kernel({rows.m_data.data() + row_sets.first, rows.m_stride},
             {m_data.data() + sets.first, m_stride}, row_sets.count, directions, sets.count, masks);
  }
  /// The masks of the set pairs inside a range of sets: masks[r] for set first + r against
  /// the sets after it (bit j for first + j, only j > r set).
  void may_meet_masks_within(Sets sets, int directions, std::uint32_t* masks) const {
    may_meet_masks(*this, sets, sets, directions, masks);
    for (int r = 0; r < sets.count; ++r) masks[r] &= ~((2u << r) - 1u);
  }

  /// Where a kernel reads: set 0's first column, and the distance between columns.
  struct View {
    const float* data;   ///< column c of set i at data + c·stride + i
    std::size_t stride;  ///< floats between two columns
  };
  /// The kernel of may_meet_masks().
  using MaskKernel = void (*)(View rows, View columns, int row_count, int directions, int count,
                              std::uint32_t* masks);

 private:
  std::size_t offset(int k, Bound bound) const {
    return static_cast<std::size_t>(4 * k + bound) * m_stride;
  }

  static const MaskKernel s_kernel;
  int m_directions = 0;
  std::size_t m_stride = 0;
  std::vector<float, UnwrittenAllocator<float>> m_data;
};

namespace detail {
/// StepBoundColumns::may_meet_masks() in SSE (any x86-64 processor; count ≤ 16) and in
/// AVX-512 (call only when lanes::has_avx512()); exposed so that a test can check that they
/// agree.
void may_meet_masks_sse(StepBoundColumns::View rows, StepBoundColumns::View columns, int row_count,
                        int directions, int count, std::uint32_t* masks);
void may_meet_masks_avx512(StepBoundColumns::View rows, StepBoundColumns::View columns,
                           int row_count, int directions, int count, std::uint32_t* masks);
}  // namespace detail

}  // namespace tailor

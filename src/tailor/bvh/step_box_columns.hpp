#pragma once
/// @file
/// StepBoxes in structure-of-arrays form, so that one box is compared with sixteen at once
/// (AVX-512; eight elsewhere): the buckets at the bottom of BasicBvh<StepBox>'s walks (the
/// candidate walk of collisions with a thickness), where one node pair used to be visited per
/// pair of boxes.

#include <array>
#include <cstdint>
#include <vector>

#include "tailor/bvh/step_boxes.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor {

/// The twelve bounds of a sequence of StepBoxes (start min, start max, end min, end max; x, y,
/// z), one column each, padded by kLanes entries so that any kLanes consecutive boxes load.
class StepBoxColumns {
 public:
  /// Most boxes compared at once.
  static constexpr int kLanes = 16;
  /// The twelve columns.
  using Columns = std::array<std::vector<float>, 12>;
  /// The kernel of may_meet_mask().
  using MaskKernel = std::uint32_t (*)(const Columns&, const StepBox&, Index, int);

  /// Boxes this processor compares at once: 16 with AVX-512, 8 otherwise (two SSE vectors;
  /// sixteen in four were no faster than eight in two).
  static int lanes();

  /// Room for `n` boxes (their bounds unset until set()).
  void resize(Index n) {
    for (std::vector<float>& column : m_columns) {
      column.assign(static_cast<std::size_t>(n) + kLanes, 0.0f);
    }
  }
  /// Stores box `i`.
  void set(Index i, const StepBox& box) {
    const auto at = static_cast<std::size_t>(i);
    for (int k = 0; k < 3; ++k) {
      m_columns[kStartMin + k][at] = box.start.min[k];
      m_columns[kStartMax + k][at] = box.start.max[k];
      m_columns[kEndMin + k][at] = box.end.min[k];
      m_columns[kEndMax + k][at] = box.end.max[k];
    }
  }
  /// Box `i`.
  StepBox box(Index i) const {
    const auto at = static_cast<std::size_t>(i);
    StepBox box;
    for (int k = 0; k < 3; ++k) {
      box.start.min[k] = m_columns[kStartMin + k][at];
      box.start.max[k] = m_columns[kStartMax + k][at];
      box.end.min[k] = m_columns[kEndMin + k][at];
      box.end.max[k] = m_columns[kEndMax + k][at];
    }
    return box;
  }
  /// Bit j (j < count ≤ lanes()) set when `box` and stored box first + j may meet over the
  /// step: the same comparisons as may_meet_over_step(), lanes() boxes at a time.
  std::uint32_t may_meet_mask(const StepBox& box, Index first, int count) const {
    return s_kernel(m_columns, box, first, count);
  }

  /// The columns (each padded by kLanes entries).
  const Columns& columns() const { return m_columns; }

  static constexpr int kStartMin = 0;  ///< first column of the start box's minima (x, y, z)
  static constexpr int kStartMax = 3;  ///< first column of the start box's maxima
  static constexpr int kEndMin = 6;    ///< first column of the end box's minima
  static constexpr int kEndMax = 9;    ///< first column of the end box's maxima

 private:
  static const MaskKernel s_kernel;
  Columns m_columns;
};

namespace detail {
/// may_meet_mask() in SSE (any x86-64 processor; count ≤ 16) and in AVX-512 (call only when
/// lanes::has_avx512()); exposed so that a test can check that they agree.
std::uint32_t may_meet_mask_sse(const StepBoxColumns::Columns& columns, const StepBox& box,
                                Index first, int count);
std::uint32_t may_meet_mask_avx512(const StepBoxColumns::Columns& columns, const StepBox& box,
                                   Index first, int count);
}  // namespace detail

}  // namespace tailor

#pragma once
/// @file
/// StepBoxes in structure-of-arrays form, so that one box is compared with eight at once: the
/// buckets at the bottom of BasicBvh<StepBox>'s walks (the candidate walk of collisions with a
/// thickness), where one node pair used to be visited per pair of boxes.

#include <array>
#include <cstdint>
#include <vector>

#include <immintrin.h>

#include "tailor/bvh/step_boxes.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor {

/// The twelve bounds of a sequence of StepBoxes (start min, start max, end min, end max; x, y,
/// z), one column each, padded by kLanes entries so that any eight consecutive boxes load.
class StepBoxColumns {
 public:
  /// Boxes compared at once.
  static constexpr int kLanes = 8;

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
  /// Bit j (j < count ≤ kLanes) set when `box` and stored box first + j may meet over the step:
  /// the same comparisons as may_meet_over_step(), eight boxes at a time.
  std::uint32_t may_meet_mask(const StepBox& box, Index first, int count) const {
    std::uint32_t mask = 0;
    for (int half = 0; half < kLanes; half += 4) {
      const std::size_t at = static_cast<std::size_t>(first) + half;
      const auto column = [&](int c) { return _mm_loadu_ps(m_columns[c].data() + at); };
      __m128 apart = _mm_setzero_ps();
      for (int k = 0; k < 3; ++k) {
        apart = _mm_or_ps(
            apart, _mm_and_ps(_mm_cmplt_ps(_mm_set1_ps(box.start.max[k]), column(kStartMin + k)),
                              _mm_cmplt_ps(_mm_set1_ps(box.end.max[k]), column(kEndMin + k))));
        apart = _mm_or_ps(
            apart, _mm_and_ps(_mm_cmplt_ps(column(kStartMax + k), _mm_set1_ps(box.start.min[k])),
                              _mm_cmplt_ps(column(kEndMax + k), _mm_set1_ps(box.end.min[k]))));
      }
      mask |= static_cast<std::uint32_t>(~_mm_movemask_ps(apart) & 0xf) << half;
    }
    return mask & ((1u << count) - 1u);
  }

 private:
  static constexpr int kStartMin = 0, kStartMax = 3, kEndMin = 6, kEndMax = 9;
  std::array<std::vector<float>, 12> m_columns;
};

}  // namespace tailor

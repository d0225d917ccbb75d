/// @file
/// The kernels of StepBoundColumns::may_meet_mask(): four sets per SSE vector, sixteen per
/// AVX-512 vector.

#include "tailor/bvh/step_bound_columns.hpp"

#include <immintrin.h>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {

namespace detail {

void may_meet_masks_sse(StepBoundColumns::View rows, StepBoundColumns::View columns, int row_count,
                        int directions, int count, std::uint32_t* masks) {
  const std::uint32_t in_count = (std::uint32_t{1} << count) - 1u;
  for (int r = 0; r < row_count; ++r) {
    std::uint32_t mask = 0;
    for (int group = 0; group < count; group += 4) {
      __m128 apart = _mm_setzero_ps();
      for (int k = 0; k < directions; ++k) {
        const float* at = columns.data + 4 * k * columns.stride + group;
        const float* row = rows.data + 4 * k * rows.stride + r;
        const __m128 start_min = _mm_loadu_ps(at), start_max = _mm_loadu_ps(at + columns.stride);
        const __m128 end_min = _mm_loadu_ps(at + 2 * columns.stride);
        const __m128 end_max = _mm_loadu_ps(at + 3 * columns.stride);
        apart =
            _mm_or_ps(apart, _mm_and_ps(_mm_cmplt_ps(_mm_set1_ps(row[rows.stride]), start_min),
                                        _mm_cmplt_ps(_mm_set1_ps(row[3 * rows.stride]), end_min)));
        apart =
            _mm_or_ps(apart, _mm_and_ps(_mm_cmplt_ps(start_max, _mm_set1_ps(row[0])),
                                        _mm_cmplt_ps(end_max, _mm_set1_ps(row[2 * rows.stride]))));
      }
      mask |= static_cast<std::uint32_t>(~_mm_movemask_ps(apart) & 0xf) << group;
    }
    masks[r] = mask & in_count;
  }
}

// Direction by direction: its four column vectors are loaded once for all the rows.
[[gnu::target("avx512f")]] void may_meet_masks_avx512(StepBoundColumns::View rows,
                                                      StepBoundColumns::View columns, int row_count,
                                                      int directions, int count,
                                                      std::uint32_t* masks) {
  std::uint32_t apart[StepBoundColumns::kLanes * 2] = {};
  for (int k = 0; k < directions; ++k) {
    const float* at = columns.data + 4 * k * columns.stride;
    const __m512 start_min = _mm512_loadu_ps(at), start_max = _mm512_loadu_ps(at + columns.stride);
    const __m512 end_min = _mm512_loadu_ps(at + 2 * columns.stride);
    const __m512 end_max = _mm512_loadu_ps(at + 3 * columns.stride);
    const float* row = rows.data + 4 * k * rows.stride;
    for (int r = 0; r < row_count; ++r, ++row) {
      apart[r] |= _mm512_cmp_ps_mask(_mm512_set1_ps(row[rows.stride]), start_min, _CMP_LT_OQ) &
                  _mm512_cmp_ps_mask(_mm512_set1_ps(row[3 * rows.stride]), end_min, _CMP_LT_OQ);
      apart[r] |= _mm512_cmp_ps_mask(start_max, _mm512_set1_ps(row[0]), _CMP_LT_OQ) &
                  _mm512_cmp_ps_mask(end_max, _mm512_set1_ps(row[2 * rows.stride]), _CMP_LT_OQ);
    }
  }
  const std::uint32_t in_count = (std::uint32_t{1} << count) - 1u;
  for (int r = 0; r < row_count; ++r) masks[r] = ~apart[r] & in_count;
}

}  // namespace detail

int StepBoundColumns::lanes() {
  static const int lanes = lanes::has_avx512() ? 16 : 8;
  return lanes;
}

const StepBoundColumns::MaskKernel StepBoundColumns::s_kernel =
    lanes::has_avx512() ? detail::may_meet_masks_avx512 : detail::may_meet_masks_sse;

}  // namespace tailor

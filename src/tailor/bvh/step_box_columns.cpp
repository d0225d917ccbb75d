/// @file
/// The kernels of StepBoxColumns::may_meet_mask(): four boxes per SSE vector, sixteen per
/// AVX-512 vector.

#include "tailor/bvh/step_box_columns.hpp"

#include <immintrin.h>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {

namespace detail {

std::uint32_t may_meet_mask_sse(const StepBoxColumns::Columns& columns, const StepBox& box,
                                Index first, int count) {
  using C = StepBoxColumns;
  std::uint32_t mask = 0;
  for (int group = 0; group < count; group += 4) {
    const std::size_t at = static_cast<std::size_t>(first) + group;
    const auto column = [&](int c) { return _mm_loadu_ps(columns[c].data() + at); };
    __m128 apart = _mm_setzero_ps();
    for (int k = 0; k < 3; ++k) {
      apart = _mm_or_ps(
          apart, _mm_and_ps(_mm_cmplt_ps(_mm_set1_ps(box.start.max[k]), column(C::kStartMin + k)),
                            _mm_cmplt_ps(_mm_set1_ps(box.end.max[k]), column(C::kEndMin + k))));
      apart = _mm_or_ps(
          apart, _mm_and_ps(_mm_cmplt_ps(column(C::kStartMax + k), _mm_set1_ps(box.start.min[k])),
                            _mm_cmplt_ps(column(C::kEndMax + k), _mm_set1_ps(box.end.min[k]))));
    }
    mask |= static_cast<std::uint32_t>(~_mm_movemask_ps(apart) & 0xf) << group;
  }
  return mask & ((1u << count) - 1u);
}

// The loads are written out (a lambda would be compiled without the AVX-512 target).
[[gnu::target("avx512f")]] std::uint32_t may_meet_mask_avx512(
    const StepBoxColumns::Columns& columns, const StepBox& box, Index first, int count) {
  using C = StepBoxColumns;
  const std::size_t at = static_cast<std::size_t>(first);
  __mmask16 apart = 0;
  for (int k = 0; k < 3; ++k) {
    const __m512 start_min = _mm512_loadu_ps(columns[C::kStartMin + k].data() + at);
    const __m512 start_max = _mm512_loadu_ps(columns[C::kStartMax + k].data() + at);
    const __m512 end_min = _mm512_loadu_ps(columns[C::kEndMin + k].data() + at);
    const __m512 end_max = _mm512_loadu_ps(columns[C::kEndMax + k].data() + at);
    apart |= _mm512_cmp_ps_mask(_mm512_set1_ps(box.start.max[k]), start_min, _CMP_LT_OQ) &
             _mm512_cmp_ps_mask(_mm512_set1_ps(box.end.max[k]), end_min, _CMP_LT_OQ);
    apart |= _mm512_cmp_ps_mask(start_max, _mm512_set1_ps(box.start.min[k]), _CMP_LT_OQ) &
             _mm512_cmp_ps_mask(end_max, _mm512_set1_ps(box.end.min[k]), _CMP_LT_OQ);
  }
  return static_cast<std::uint32_t>(static_cast<std::uint16_t>(~apart)) & ((1u << count) - 1u);
}

}  // namespace detail

int StepBoxColumns::lanes() {
  static const int lanes = lanes::has_avx512() ? 16 : 8;
  return lanes;
}

const StepBoxColumns::MaskKernel StepBoxColumns::s_kernel =
    lanes::has_avx512() ? detail::may_meet_mask_avx512 : detail::may_meet_mask_sse;

}  // namespace tailor

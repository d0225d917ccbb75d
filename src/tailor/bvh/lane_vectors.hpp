#pragma once
/// @file
/// GCC/Clang vectors of W doubles for the lane kernels over a MovingTriangleBatch
/// (direction_mask.cpp): W = 2 is the width of SSE2 (wider generic vectors
/// are lowered lane by lane there); W = 4 is used only inside functions built for AVX2,
/// chosen at run time (has_avx2()), where it maps to ymm registers, and W = 8 only inside
/// functions built for AVX-512 (has_avx512(): zmm registers). Internal to the bvh module.

#include <cstdint>
#include <cstring>
#include <limits>

// The four-lane helpers are always inlined into the AVX2 functions, so no AVX vector ever
// crosses a call: GCC's warning about the ABI of such calls does not apply.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wunknown-warning-option"
#endif
#pragma GCC diagnostic ignored "-Wpsabi"

namespace tailor::lanes {

/// Lanes and comparison masks of width W (explicit specialisations: GCC drops a
/// vector_size that depends on a template parameter).
template <int W>
struct Vectors;
template <>
struct Vectors<2> {
  using Lanes = double __attribute__((vector_size(16)));
  using Bits = std::int64_t __attribute__((vector_size(16)));
};
template <>
struct Vectors<4> {
  using Lanes = double __attribute__((vector_size(32)));
  using Bits = std::int64_t __attribute__((vector_size(32)));
};
template <>
struct Vectors<8> {
  using Lanes = double __attribute__((vector_size(64)));
  using Bits = std::int64_t __attribute__((vector_size(64)));
};

template <int W>
[[gnu::always_inline]] inline typename Vectors<W>::Lanes load(const double* p) {
  typename Vectors<W>::Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class Lanes>
[[gnu::always_inline]] inline Lanes abs(Lanes v) {
  using Bits = decltype(v < v);
  return (Lanes)((Bits)v & std::numeric_limits<std::int64_t>::max());
}
/// Whether this processor runs the AVX2 kernels (checked once).
inline bool has_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}
/// Whether it runs the AVX-512 kernels (F and DQ, with AVX2; checked once).
inline bool has_avx512() {
  static const bool avx512 =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && has_avx2();
  return avx512;
}

}  // namespace tailor::lanes

#pragma once
/// @file
/// GCC/Clang vectors of W doubles and of F floats for the lane kernels over a
/// MovingTriangleBatch (batch_bounds.cpp, direction_mask.cpp): W = 2 doubles or F = 4
/// floats is the width of SSE2 (wider generic vectors are lowered lane by lane there);
/// W = 4 and F = 8 are used only inside functions built for AVX2, chosen at run time
/// (has_avx2()), where they map to ymm registers, and W = 8 and F = 16 only inside
/// functions built for AVX-512 (has_avx512(): zmm registers). Internal to the bvh module.

#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

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

/// Lanes of F floats and comparison masks (F = 2 only as the result of converting two
/// doubles).
template <int F>
struct FloatVectors;
template <>
struct FloatVectors<2> {
  using Lanes = float __attribute__((vector_size(8)));
  using Bits = std::int32_t __attribute__((vector_size(8)));
};
template <>
struct FloatVectors<4> {
  using Lanes = float __attribute__((vector_size(16)));
  using Bits = std::int32_t __attribute__((vector_size(16)));
};
template <>
struct FloatVectors<8> {
  using Lanes = float __attribute__((vector_size(32)));
  using Bits = std::int32_t __attribute__((vector_size(32)));
};
template <>
struct FloatVectors<16> {
  using Lanes = float __attribute__((vector_size(64)));
  using Bits = std::int32_t __attribute__((vector_size(64)));
};

template <int W>
[[gnu::always_inline]] inline typename Vectors<W>::Lanes load(const double* p) {
  typename Vectors<W>::Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
/// |v| per lane (doubles or floats): the sign bits cleared.
template <class Lanes>
[[gnu::always_inline]] inline Lanes abs(Lanes v) {
  using Bits = decltype(v < v);
  using Integer = std::remove_cvref_t<decltype(Bits{}[0])>;
  return (Lanes)((Bits)v & std::numeric_limits<Integer>::max());
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

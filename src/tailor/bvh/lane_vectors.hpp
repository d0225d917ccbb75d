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

/// N lanes of T (double or float) and the comparison masks of such lanes. (typedef, not
/// `using`: GCC drops a vector_size attribute that depends on a template parameter from an
/// alias declaration, but keeps it on a typedef.)
template <class T, int N>
struct LaneVectors {
  /// Signed integer of T's width (the lane type of comparison masks).
  using Integer = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;
  /// N lanes of T (a GCC vector type).
  typedef T Lanes __attribute__((vector_size(N * sizeof(T))));
  /// N lanes of Integer: the result of comparing two Lanes (all bits set where true).
  typedef Integer Bits __attribute__((vector_size(N * sizeof(T))));
};
/// W doubles (W = 2, 4, 8).
template <int W>
using Vectors = LaneVectors<double, W>;
/// F floats (F = 4, 8, 16; F = 2 only as the result of converting two doubles).
template <int F>
using FloatVectors = LaneVectors<float, F>;

/// Loads W doubles from `p` (no alignment needed).
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
/// Per lane, a float <= x (float_at_most, float_box.hpp) clamped to the float range, without
/// branches: x - |x|·2^-23 - 2^-149 is below x by more than half a float ulp, so rounding it
/// to the nearest float cannot land above x.
template <int W>
[[gnu::always_inline]] inline typename FloatVectors<W>::Lanes float_below(
    typename Vectors<W>::Lanes x) {
  using Lanes = typename Vectors<W>::Lanes;
  const Lanes top = Lanes{} + double{std::numeric_limits<float>::max()};
  Lanes nudged = x - abs(x) * 0x1p-23 - 0x1p-149;
  nudged = top < nudged ? top : nudged;
  nudged = nudged < -top ? -top : nudged;
  return __builtin_convertvector(nudged, typename FloatVectors<W>::Lanes);
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
/// The widest build of a kernel this processor runs: `avx512` (F and DQ), else `avx2`,
/// else `sse2` (every x86-64 processor). Each kernel's public entry calls the one this
/// picks.
template <class Kernel>
Kernel widest(Kernel avx512, Kernel avx2, Kernel sse2) {
  return has_avx512() ? avx512 : has_avx2() ? avx2 : sse2;
}
/// The same for a kernel without an AVX-512 build.
template <class Kernel>
Kernel widest(Kernel avx2, Kernel sse2) {
  return has_avx2() ? avx2 : sse2;
}

}  // namespace tailor::lanes

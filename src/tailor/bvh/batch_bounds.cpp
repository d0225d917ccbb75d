#include "tailor/bvh/batch_bounds.hpp"

#include <cstring>
#include <limits>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

constexpr double kFloatMax = std::numeric_limits<float>::max();

// Per lane, a float <= x (float_at_most, float_box.hpp) clamped to the float range, without
// branches: x - |x|·2^-23 - 2^-149 is below x by more than half a float ulp, so rounding it
// to the nearest float cannot land above x.
template <int W>
[[gnu::always_inline]] inline typename lanes::FloatVectors<W>::Lanes float_below(
    typename lanes::Vectors<W>::Lanes x) {
  using Lanes = typename lanes::Vectors<W>::Lanes;
  const Lanes top = Lanes{} + kFloatMax;
  Lanes nudged = x - lanes::abs(x) * 0x1p-23 - 0x1p-149;
  nudged = top < nudged ? top : nudged;
  nudged = nudged < -top ? -top : nudged;
  return __builtin_convertvector(nudged, typename lanes::FloatVectors<W>::Lanes);
}

// The bounds of lanes i to i + W.
template <int W>
[[gnu::always_inline]] inline void lane_bounds(const MovingTriangleBatch& batch, int i,
                                               BatchBounds& out) {
  using Lanes = typename lanes::Vectors<W>::Lanes;
  const auto& c = batch.coordinate;
  for (int k = 0; k < 3; ++k) {
    Lanes lo = lanes::load<W>(c[k] + i), hi = lo;
    for (int corner = 1; corner < 6; ++corner) {
      const Lanes x = lanes::load<W>(c[3 * corner + k] + i);
      lo = x < lo ? x : lo;
      hi = hi < x ? x : hi;
    }
    const auto below = float_below<W>(lo), above = -float_below<W>(-hi);
    std::memcpy(&out.low[k][i], &below, sizeof below);
    std::memcpy(&out.high[k][i], &above, sizeof above);
  }
}

template <int W>
[[gnu::always_inline]] inline void bounds(const MovingTriangleBatch& batch, BatchBounds& out) {
  for (int i = 0; i < batch.padded_count(); i += W) lane_bounds<W>(batch, i, out);
}

[[gnu::target("avx2")]] void bounds_avx2(const MovingTriangleBatch& batch, BatchBounds& out) {
  bounds<4>(batch, out);
}

// Eight lanes at a time, the last four (a batch is padded to a multiple of four) as above.
[[gnu::target("avx512f,avx512dq,avx2")]] void bounds_avx512(const MovingTriangleBatch& batch,
                                                            BatchBounds& out) {
  int i = 0;
  for (; i + 8 <= batch.padded_count(); i += 8) lane_bounds<8>(batch, i, out);
  if (i < batch.padded_count()) lane_bounds<4>(batch, i, out);
}

}  // namespace

namespace detail {

void batch_bounds_two_lanes(const MovingTriangleBatch& batch, BatchBounds& bounds) {
  tailor::bounds<2>(batch, bounds);
}

void batch_bounds_four_lanes(const MovingTriangleBatch& batch, BatchBounds& bounds) {
  bounds_avx2(batch, bounds);
}

void batch_bounds_eight_lanes(const MovingTriangleBatch& batch, BatchBounds& bounds) {
  bounds_avx512(batch, bounds);
}

}  // namespace detail

void batch_bounds(const MovingTriangleBatch& batch, BatchBounds& bounds) {
  lanes::widest(detail::batch_bounds_eight_lanes, detail::batch_bounds_four_lanes,
                detail::batch_bounds_two_lanes)(batch, bounds);
}

}  // namespace tailor

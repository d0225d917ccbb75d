#include "tailor/bvh/batch_bounds.hpp"

#include <cstring>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// The bounds of lanes i to i + W of the corners `first_corner` to first_corner + 2 (one
// frame).
template <int W>
[[gnu::always_inline]] inline void lane_bounds(const MovingTriangleBatch& batch, int i,
                                               int first_corner, BatchBounds& out) {
  using Lanes = typename lanes::Vectors<W>::Lanes;
  const auto& c = batch.coordinate;
  for (int k = 0; k < 3; ++k) {
    Lanes lo = lanes::load<W>(c[3 * first_corner + k] + i), hi = lo;
    for (int corner = first_corner + 1; corner < first_corner + 3; ++corner) {
      const Lanes x = lanes::load<W>(c[3 * corner + k] + i);
      lo = x < lo ? x : lo;
      hi = hi < x ? x : hi;
    }
    const auto below = lanes::float_below<W>(lo), above = -lanes::float_below<W>(-hi);
    std::memcpy(&out.low[k][i], &below, sizeof below);
    std::memcpy(&out.high[k][i], &above, sizeof above);
  }
}

// Both frames of lanes i to i + W (corners 0-2 at t = 0, 3-5 at t = 1).
template <int W>
[[gnu::always_inline]] inline void lane_bounds(const MovingTriangleBatch& batch, int i,
                                               BatchBounds& start, BatchBounds& end) {
  lane_bounds<W>(batch, i, 0, start);
  lane_bounds<W>(batch, i, 3, end);
}

template <int W>
[[gnu::always_inline]] inline void bounds(const MovingTriangleBatch& batch, BatchBounds& start,
                                          BatchBounds& end) {
  for (int i = 0; i < batch.padded_count(); i += W) lane_bounds<W>(batch, i, start, end);
}

[[gnu::target("avx2")]] void bounds_avx2(const MovingTriangleBatch& batch, BatchBounds& start,
                                         BatchBounds& end) {
  bounds<4>(batch, start, end);
}

// Eight lanes at a time, the last four (a batch is padded to a multiple of four) as above.
[[gnu::target("avx512f,avx512dq,avx2")]] void bounds_avx512(const MovingTriangleBatch& batch,
                                                            BatchBounds& start, BatchBounds& end) {
  int i = 0;
  for (; i + 8 <= batch.padded_count(); i += 8) lane_bounds<8>(batch, i, start, end);
  if (i < batch.padded_count()) lane_bounds<4>(batch, i, start, end);
}

}  // namespace

namespace detail {

void batch_bounds_two_lanes(const MovingTriangleBatch& batch, BatchBounds& start,
                            BatchBounds& end) {
  tailor::bounds<2>(batch, start, end);
}

void batch_bounds_four_lanes(const MovingTriangleBatch& batch, BatchBounds& start,
                             BatchBounds& end) {
  bounds_avx2(batch, start, end);
}

void batch_bounds_eight_lanes(const MovingTriangleBatch& batch, BatchBounds& start,
                              BatchBounds& end) {
  bounds_avx512(batch, start, end);
}

}  // namespace detail

void batch_bounds(const MovingTriangleBatch& batch, BatchBounds& start, BatchBounds& end) {
  lanes::widest(detail::batch_bounds_eight_lanes, detail::batch_bounds_four_lanes,
                detail::batch_bounds_two_lanes)(batch, start, end);
}

}  // namespace tailor

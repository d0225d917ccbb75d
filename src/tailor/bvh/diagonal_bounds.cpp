#include "tailor/bvh/diagonal_bounds.hpp"

#include <cstring>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// The diagonal bounds of lanes i to i + W of the corners `first_corner` to first_corner + 2
// (one frame): per direction, the least p - e and the greatest p + e (the header's margin),
// rounded outward to float.
template <int W>
[[gnu::always_inline]] inline void diagonal_lane_bounds(const MovingTriangleBatch& batch, int i,
                                                        int first_corner,
                                                        DiagonalBatchBounds& out) {
  using Lanes = typename lanes::Vectors<W>::Lanes;
  const auto& c = batch.coordinate;
  Lanes low[kDiagonals], high[kDiagonals];
  for (int corner = first_corner; corner < first_corner + 3; ++corner) {
    const Lanes x = lanes::load<W>(c[3 * corner] + i);
    const Lanes y = lanes::load<W>(c[3 * corner + 1] + i);
    const Lanes z = lanes::load<W>(c[3 * corner + 2] + i);
    const Lanes margin = (lanes::abs(x) + lanes::abs(y) + lanes::abs(z)) * 0x1p-50;
    const Lanes p[kDiagonals] = {x + y + z, x + y - z, x - y + z, y + z - x};
    for (int k = 0; k < kDiagonals; ++k) {
      const Lanes lo = p[k] - margin, hi = p[k] + margin;
      if (corner == first_corner) {
        low[k] = lo;
        high[k] = hi;
      } else {
        low[k] = lo < low[k] ? lo : low[k];
        high[k] = high[k] < hi ? hi : high[k];
      }
    }
  }
  for (int k = 0; k < kDiagonals; ++k) {
    const auto below = lanes::float_below<W>(low[k]), above = -lanes::float_below<W>(-high[k]);
    std::memcpy(&out.low[k][i], &below, sizeof below);
    std::memcpy(&out.high[k][i], &above, sizeof above);
  }
}

template <int W>
[[gnu::always_inline]] inline void diagonal_bounds(const MovingTriangleBatch& batch,
                                                   DiagonalBatchBounds& start,
                                                   DiagonalBatchBounds& end) {
  for (int i = 0; i < batch.padded_count(); i += W) {
    diagonal_lane_bounds<W>(batch, i, 0, start);
    diagonal_lane_bounds<W>(batch, i, 3, end);
  }
}

void diagonal_bounds_sse2(const MovingTriangleBatch& batch, DiagonalBatchBounds& start,
                          DiagonalBatchBounds& end) {
  diagonal_bounds<2>(batch, start, end);
}

[[gnu::target("avx2")]] void diagonal_bounds_avx2(const MovingTriangleBatch& batch,
                                                  DiagonalBatchBounds& start,
                                                  DiagonalBatchBounds& end) {
  diagonal_bounds<4>(batch, start, end);
}

// Eight lanes at a time, the last four (a batch is padded to a multiple of four) as above.
[[gnu::target("avx512f,avx512dq,avx2")]] void diagonal_bounds_avx512(
    const MovingTriangleBatch& batch, DiagonalBatchBounds& start, DiagonalBatchBounds& end) {
  int i = 0;
  for (; i + 8 <= batch.padded_count(); i += 8) {
    diagonal_lane_bounds<8>(batch, i, 0, start);
    diagonal_lane_bounds<8>(batch, i, 3, end);
  }
  if (i < batch.padded_count()) {
    diagonal_lane_bounds<4>(batch, i, 0, start);
    diagonal_lane_bounds<4>(batch, i, 3, end);
  }
}

}  // namespace

void diagonal_batch_bounds(const MovingTriangleBatch& batch, DiagonalBatchBounds& start,
                           DiagonalBatchBounds& end) {
  lanes::widest(diagonal_bounds_avx512, diagonal_bounds_avx2, diagonal_bounds_sse2)(batch, start,
                                                                                    end);
}

}  // namespace tailor

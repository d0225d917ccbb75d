#include "tailor/geometry/coplanarity_batch.hpp"

#include <cstdint>

#include "tailor/geometry/lane_vectors.hpp"

namespace tailor {
namespace {

using lanes::abs;
using lanes::Vectors;

using Terms = std::array<CoplanarityTerms, CoplanarityBatch::kCapacity>;

template <int W>
using Lanes = typename Vectors<W>::Lanes;

// p × q as in the scalar function, and the same with absolute values of the products.
template <int W>
struct Cross {
  Lanes<W> r[3], m[3];
};
template <int W>
[[gnu::always_inline]] inline Cross<W> cross(const Lanes<W>* p, const Lanes<W>* q) {
  const Lanes<W> p1q2 = p[1] * q[2], p2q1 = p[2] * q[1];
  const Lanes<W> p2q0 = p[2] * q[0], p0q2 = p[0] * q[2];
  const Lanes<W> p0q1 = p[0] * q[1], p1q0 = p[1] * q[0];
  Cross<W> c;
  c.r[0] = p1q2 - p2q1, c.r[1] = p2q0 - p0q2, c.r[2] = p0q1 - p1q0;
  c.m[0] = abs(p1q2) + abs(p2q1), c.m[1] = abs(p2q0) + abs(p0q2), c.m[2] = abs(p0q1) + abs(p1q0);
  return c;
}
template <int W>
[[gnu::always_inline]] inline Lanes<W> dot(const Lanes<W>* p, const Lanes<W>* q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
template <int W>
[[gnu::always_inline]] inline Lanes<W> dot_abs(const Lanes<W>* p, const Lanes<W>* q) {
  return abs(p[0]) * q[0] + abs(p[1]) * q[1] + abs(p[2]) * q[2];
}

// The lanes [first, first + W) of a batch, each term written as in
// detail::coplanarity_bernstein_double() (coplanarity_sign.hpp), operation for operation.
template <int W>
[[gnu::always_inline]] inline void lanes_from(const CoplanarityBatch& batch, int first,
                                              Terms& terms) {
  using Bits = typename Vectors<W>::Bits;
  // Lanes past the batch's count repeat its first query (computed, never written back).
  const double* points[8][W];
  for (int lane = 0; lane < W; ++lane) {
    const int query = first + lane < batch.count ? first + lane : 0;
    for (int p = 0; p < 8; ++p) points[p][lane] = batch.points[query][p];
  }
  // The 18 differences u, v, w at t = 0 (points 1-3 minus 0) and t = 1 (5-7 minus 4).
  Lanes<W> d[6][3];
  for (int k = 0; k < 3; ++k) {
    Lanes<W> x[8];
    for (int p = 0; p < 8; ++p) {
      double coordinate[W];
      for (int lane = 0; lane < W; ++lane) coordinate[lane] = points[p][lane][k];
      x[p] = lanes::load<W>(coordinate);
    }
    for (int i = 0; i < 3; ++i) {
      d[i][k] = x[1 + i] - x[0];
      d[3 + i][k] = x[5 + i] - x[4];
    }
  }
  const Lanes<W>*u0 = d[0], *v0 = d[1], *w0 = d[2], *u1 = d[3], *v1 = d[4], *w1 = d[5];
  // The range guard: every difference zero or of magnitude in [2^-250, 2^250].
  const Lanes<W> zero{}, low = zero + 0x1p-250, high = zero + 0x1p250;
  Bits in_range = zero == zero;
  for (const auto& x : d) {
    for (int k = 0; k < 3; ++k) {
      const Lanes<W> m = abs(x[k]);
      in_range &= (m == zero) | ((m >= low) & (m <= high));
    }
  }
  const Cross<W> c00 = cross<W>(v0, w0), c11 = cross<W>(v1, w1), c01 = cross<W>(v0, w1),
                 c10 = cross<W>(v1, w0);
  const Lanes<W> value[4] = {
      dot<W>(u0, c00.r), dot<W>(u1, c00.r) + dot<W>(u0, c10.r) + dot<W>(u0, c01.r),
      dot<W>(u0, c11.r) + dot<W>(u1, c01.r) + dot<W>(u1, c10.r), dot<W>(u1, c11.r)};
  const Lanes<W> bound[4] = {
      0x1p-49 * dot_abs<W>(u0, c00.m),
      0x1p-49 * (dot_abs<W>(u1, c00.m) + dot_abs<W>(u0, c10.m) + dot_abs<W>(u0, c01.m)),
      0x1p-49 * (dot_abs<W>(u0, c11.m) + dot_abs<W>(u1, c01.m) + dot_abs<W>(u1, c10.m)),
      0x1p-49 * dot_abs<W>(u1, c11.m)};
  for (int lane = 0; lane < W && first + lane < batch.count; ++lane) {
    CoplanarityTerms& out = terms[first + lane];
    out.ok = in_range[lane] != 0;
    for (int i = 0; i < 4; ++i) out.value[i] = value[i][lane], out.bound[i] = bound[i][lane];
  }
}

template <int W>
[[gnu::always_inline]] inline void all_lanes(const CoplanarityBatch& batch, Terms& terms) {
  for (int first = 0; first < batch.count; first += W) lanes_from<W>(batch, first, terms);
}

[[gnu::target("avx2")]] void all_lanes_avx2(const CoplanarityBatch& batch, Terms& terms) {
  all_lanes<4>(batch, terms);
}

}  // namespace

namespace detail {

void coplanarity_bernstein_two_lanes(const CoplanarityBatch& batch, Terms& terms) {
  all_lanes<2>(batch, terms);
}

void coplanarity_bernstein_four_lanes(const CoplanarityBatch& batch, Terms& terms) {
  all_lanes_avx2(batch, terms);
}

bool coplanarity_batch_has_four_lanes() {
  return lanes::has_avx2();
}

}  // namespace detail

void coplanarity_bernstein_batch(const CoplanarityBatch& batch, Terms& terms) {
  if (lanes::has_avx2()) {
    detail::coplanarity_bernstein_four_lanes(batch, terms);
  } else {
    detail::coplanarity_bernstein_two_lanes(batch, terms);
  }
}

}  // namespace tailor

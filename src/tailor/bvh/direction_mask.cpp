#include "tailor/bvh/direction_mask.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// The 13 directions c_j (first nonzero component +1), in bit order.
constexpr int kDirections[13][3] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},  {1, 1, 0},  {1, -1, 0},
                                    {1, 0, 1},  {1, 0, -1}, {0, 1, 1},  {0, 1, -1}, {1, 1, 1},
                                    {1, 1, -1}, {1, -1, 1}, {1, -1, -1}};

using lanes::FloatVectors;

// The four edge vectors of F triangles, u0, v0, u1, v1 (u = b - a, v = c - a at t = 0 and
// t = 1), three coordinates each: each the difference of two batch rows computed in double
// and rounded to float.
template <int F>
struct EdgeLanes {
  typename FloatVectors<F>::Lanes coordinate[12];
};

// The rows (to, from) of each of the twelve, in EdgeLanes order.
constexpr int kEdgeRows[12][2] = {{3, 0},  {4, 1},   {5, 2},   {6, 0},  {7, 1},   {8, 2},
                                  {12, 9}, {13, 10}, {14, 11}, {15, 9}, {16, 10}, {17, 11}};

template <int F>
[[gnu::always_inline]] inline typename FloatVectors<F>::Lanes l1(
    const typename FloatVectors<F>::Lanes* v) {
  return lanes::abs(v[0]) + lanes::abs(v[1]) + lanes::abs(v[2]);
}

// Per lane, the mask of its triangle.
//
// Error analysis (the argument is in direction_mask.hpp). Let U, V be an exact edge
// vector pair and u, v the floats used: each coordinate is rounded twice (the double
// difference, then to float), so |u_k - U_k| <= ε|u_k| + τ with ε = 2^-23, τ = 2^-149
// (τ for a float below the normal range). Each component of a computed cross product
// fl(u×v) is then within 3.1ε·(|u_i||v_j| + |u_j||v_i|) + 1.01τ·(|u_i| + |v_j| + |u_j| +
// |v_i|) + 2^-148 of the exact U×V (two rounded products, one rounded difference, and the
// input errors); summed over the components (a bound on the 2-norm), and generously:
//   e(u, v) = 2^-21·(|u|₁ + 2^-126)(|v|₁ + 2^-126) + 2^-146.
// m = ñX (two cross products, one rounded sum, a halving) is within (e(u0, v1) +
// e(u1, v0)) / 2 + 2^-24·(|u0|₁|v1|₁ + |u1|₁|v0|₁) <= e(u0, v1) + e(u1, v0) of the exact
// nX; so e0 + eX + e1 <= 2^-21·(|u0|₁ + |u1|₁ + 2^-125)(|v0|₁ + |v1|₁ + 2^-125) + 2^-144
// (the product's terms are the four pairs of e). For d with components in {-1, 0, 1}
// (|d|₂ < 2): n_i·d >= ñ_i·d - 2 e_i >= m·d - |ñ_i - m|₁ - 2 e_i. The computed δ =
// |ñ0 - m|₁ + |ñ1 - m|₁ is at least max_i |ñ_i - m|₁·(1 - 2^-21); the computed m·d (at most
// two additions of terms bounded by |m|₁) is within 2^-22·|m|₁ of m·d. So
//   fl(m·d) > δ(1 + 2^-19) + 2^-21·|m|₁ + 2·errors + 2^-126
// proves n_i·d > 0 for i = 0, X, 1: each term has at least twice what it must cover, which
// absorbs the few roundings of the threshold, and 2^-126 covers the constants (2^-144 and
// the roundings below the normal range). A coordinate beyond the float range rounds to an
// infinity; an overflowing product or sum makes the threshold infinite or NaN (|m|₁ bounds
// every dot), and every comparison with it false: no direction, never a wrong one.
template <int F>
[[gnu::always_inline]] inline typename FloatVectors<F>::Bits float_lane_masks(
    const EdgeLanes<F>& e) {
  using Lanes = typename FloatVectors<F>::Lanes;
  using Bits = typename FloatVectors<F>::Bits;
  const Lanes* u0 = e.coordinate;
  const Lanes* v0 = e.coordinate + 3;
  const Lanes* u1 = e.coordinate + 6;
  const Lanes* v1 = e.coordinate + 9;
  // n0 = u0×v0, n1 = u1×v1, m = (u0×v1 + u1×v0) / 2.
  const Lanes m[3] = {0.5f * ((u0[1] * v1[2] - u0[2] * v1[1]) + (u1[1] * v0[2] - u1[2] * v0[1])),
                      0.5f * ((u0[2] * v1[0] - u0[0] * v1[2]) + (u1[2] * v0[0] - u1[0] * v0[2])),
                      0.5f * ((u0[0] * v1[1] - u0[1] * v1[0]) + (u1[0] * v0[1] - u1[1] * v0[0]))};
  const Lanes n0_m[3] = {(u0[1] * v0[2] - u0[2] * v0[1]) - m[0],
                         (u0[2] * v0[0] - u0[0] * v0[2]) - m[1],
                         (u0[0] * v0[1] - u0[1] * v0[0]) - m[2]};
  const Lanes n1_m[3] = {(u1[1] * v1[2] - u1[2] * v1[1]) - m[0],
                         (u1[2] * v1[0] - u1[0] * v1[2]) - m[1],
                         (u1[0] * v1[1] - u1[1] * v1[0]) - m[2]};
  const Lanes delta = l1<F>(n0_m) + l1<F>(n1_m);
  const Lanes errors =
      0x1p-21f * ((l1<F>(u0) + l1<F>(u1) + 0x1p-125f) * (l1<F>(v0) + l1<F>(v1) + 0x1p-125f));
  const Lanes threshold = delta * (1 + 0x1p-19f) + 0x1p-21f * l1<F>(m) + 2 * errors + 0x1p-126f;
  const Lanes negative_threshold = -threshold;
  // Dot products in the order of kDirections, each as at most two additions.
  const Lanes x = m[0], y = m[1], z = m[2];
  const Lanes xy = x + y, x_y = x - y;
  const Lanes dots[13] = {x,     y,     z,      xy,     x_y,     x + z,  x - z,
                          y + z, y - z, xy + z, xy - z, x_y + z, x_y - z};
  Bits mask = {};
  for (int j = 0; j < 13; ++j) {
    mask |= (dots[j] > threshold) & (std::int32_t{1} << (2 * j));
    mask |= (dots[j] < negative_threshold) & (std::int32_t{1} << (2 * j + 1));
  }
  return mask;
}

// Stores the lanes' masks (through memory: no vector crosses the call from the functions
// built for wider instruction sets).
template <int F>
[[gnu::always_inline]] inline void store_lane_masks(const EdgeLanes<F>& e, DirectionMask* out) {
  const typename FloatVectors<F>::Bits bits = float_lane_masks<F>(e);
  for (int i = 0; i < F; ++i) out[i] = static_cast<DirectionMask>(bits[i]);
}

// SSE2: four lanes (two doubles per register: two differences, rounded and joined) at a
// time; a padded batch has a multiple of four lanes.
void batch_masks_sse2(const MovingTriangleBatch& batch, LaneMasks& masks) {
  const auto& c = batch.coordinate;
  for (int first = 0; first < batch.padded_count(); first += 4) {
    EdgeLanes<4> e;
    for (int k = 0; k < 12; ++k) {
      const double* to = c[kEdgeRows[k][0]] + first;
      const double* from = c[kEdgeRows[k][1]] + first;
      const __m128 low = _mm_cvtpd_ps(_mm_sub_pd(_mm_load_pd(to), _mm_load_pd(from)));
      const __m128 high = _mm_cvtpd_ps(_mm_sub_pd(_mm_load_pd(to + 2), _mm_load_pd(from + 2)));
      e.coordinate[k] = (FloatVectors<4>::Lanes)_mm_movelh_ps(low, high);
    }
    store_lane_masks<4>(e, masks.data() + first);
  }
}

// AVX2: eight lanes at a time. When only four of them are in the padded batch, the other
// four repeat them (their masks land past the padded batch).
[[gnu::target("avx2")]] void batch_masks_avx2(const MovingTriangleBatch& batch, LaneMasks& masks) {
  const auto& c = batch.coordinate;
  const int lanes = batch.padded_count();
  for (int first = 0; first < lanes; first += 8) {
    const bool whole = first + 8 <= lanes;
    EdgeLanes<8> e;
    for (int k = 0; k < 12; ++k) {
      const double* to = c[kEdgeRows[k][0]] + first;
      const double* from = c[kEdgeRows[k][1]] + first;
      const __m128 low = _mm256_cvtpd_ps(_mm256_sub_pd(_mm256_load_pd(to), _mm256_load_pd(from)));
      const __m128 high =
          whole ? _mm256_cvtpd_ps(_mm256_sub_pd(_mm256_load_pd(to + 4), _mm256_load_pd(from + 4)))
                : low;
      e.coordinate[k] = (FloatVectors<8>::Lanes)_mm256_set_m128(high, low);
    }
    store_lane_masks<8>(e, masks.data() + first);
  }
}

// Lanes 0-7 of a row; lanes 0-3 twice when only they are in the batch. (A generic
// shuffle: GCC 12's broadcast intrinsic warns of an uninitialised operand.)
[[gnu::target("avx512f,avx512dq,avx2"), gnu::always_inline]] inline __m512d first_eight(
    const double* row, bool eight) {
  if (eight) return _mm512_load_pd(row);
  const __m256d four = _mm256_load_pd(row);
  return __builtin_shufflevector(four, four, 0, 1, 2, 3, 0, 1, 2, 3);
}

// AVX-512: sixteen lanes, the whole batch, at once. Lanes past the padded batch are not
// read: they take the doubles of lanes already in it (a batch of four lanes is broadcast
// to eight; lanes 8 + i past it keep those of lane i, by a masked load).
[[gnu::target("avx512f,avx512dq,avx2")]] void batch_masks_avx512(const MovingTriangleBatch& batch,
                                                                 LaneMasks& masks) {
  static_assert(MovingTriangleBatch::kCapacity == 16, "one sixteen-lane pass per batch");
  const auto& c = batch.coordinate;
  const int lanes = batch.padded_count();
  const bool eight = lanes >= 8;
  // Lanes 8 + i read for i < lanes - 8.
  const __mmask8 high_lanes =
      static_cast<__mmask8>(lanes <= 8 ? 0 : (1u << std::min(lanes - 8, 8)) - 1);
  EdgeLanes<16> e;
  for (int k = 0; k < 12; ++k) {
    const double* to = c[kEdgeRows[k][0]];
    const double* from = c[kEdgeRows[k][1]];
    const __m512d to_low = first_eight(to, eight), from_low = first_eight(from, eight);
    const __m512d to_high = _mm512_mask_load_pd(to_low, high_lanes, to + 8);
    const __m512d from_high = _mm512_mask_load_pd(from_low, high_lanes, from + 8);
    // (Generic conversions: GCC 12's _mm512_cvtpd_ps warns of an uninitialised operand.)
    const auto low = __builtin_convertvector((lanes::Vectors<8>::Lanes)(to_low - from_low),
                                             FloatVectors<8>::Lanes);
    const auto high = __builtin_convertvector((lanes::Vectors<8>::Lanes)(to_high - from_high),
                                              FloatVectors<8>::Lanes);
    e.coordinate[k] =
        __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  }
  store_lane_masks<16>(e, masks.data());
}

}  // namespace

namespace detail {

void lane_masks_sse2(const MovingTriangleBatch& batch, LaneMasks& masks) {
  batch_masks_sse2(batch, masks);
}

void lane_masks_avx2(const MovingTriangleBatch& batch, LaneMasks& masks) {
  batch_masks_avx2(batch, masks);
}

void lane_masks_avx512(const MovingTriangleBatch& batch, LaneMasks& masks) {
  batch_masks_avx512(batch, masks);
}

bool direction_mask_has_avx512() {
  return lanes::has_avx512();
}

bool direction_mask_has_avx2() {
  return lanes::has_avx2();
}

}  // namespace detail

Vec3 mask_direction(int k) {
  const int* c = kDirections[k / 2];
  const double sign = (k % 2 == 0) ? 1.0 : -1.0;
  return sign * Vec3(c[0], c[1], c[2]);
}

Vec3 mask_axis(DirectionMask mask) {
  Vec3 sum = Vec3::Zero();
  for (DirectionMask rest = mask; rest != 0; rest &= rest - 1) {
    sum += mask_direction(__builtin_ctz(rest));
  }
  return sum;
}

void lane_masks(const MovingTriangleBatch& batch, LaneMasks& masks) {
  if (batch.count == 0) return;
  lanes::widest(detail::lane_masks_avx512, detail::lane_masks_avx2, detail::lane_masks_sse2)(batch,
                                                                                             masks);
}

DirectionMask and_of_masks(const LaneMasks& masks, int begin, int end) {
  DirectionMask all = kAllDirections;
  for (int i = begin; i < end; ++i) all &= masks[static_cast<std::size_t>(i)];
  return all;
}

DirectionMask direction_mask(const MovingTriangleBatch& batch) {
  LaneMasks masks;
  lane_masks(batch, masks);
  return and_of_masks(masks, 0, batch.count);
}

DirectionMask direction_mask(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                             const Vec3& b1, const Vec3& c1) {
  MovingTriangleBatch batch;
  batch.add(a0.data(), b0.data(), c0.data(), a1.data(), b1.data(), c1.data());
  batch.pad();
  return direction_mask(batch);
}

}  // namespace tailor

#include "tailor/bvh/direction_mask.hpp"

#include <cstdint>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// The 13 directions c_j (first nonzero component +1), in bit order.
constexpr int kDirections[13][3] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},  {1, 1, 0},  {1, -1, 0},
                                    {1, 0, 1},  {1, 0, -1}, {0, 1, 1},  {0, 1, -1}, {1, 1, 1},
                                    {1, 1, -1}, {1, -1, 1}, {1, -1, -1}};

using lanes::abs;
using lanes::load;
using lanes::Vectors;

template <class Lanes>
[[gnu::always_inline]] inline Lanes l1(Lanes x, Lanes y, Lanes z) {
  return abs(x) + abs(y) + abs(z);
}

// Per lane, the mask of its triangle.
//
// Error analysis (the argument is in direction_mask.hpp). ñ0, m = ñX, ñ1 are the computed
// control normals; each is within e_i (2-norm) of the exact one, with the generous bound
// e = 2^-48·|u|₁|v|₁ per cross product of rounded differences (each component of a rounded
// cross product is within 3·2^-53·|u|₁|v|₁ of the exact one). For d with components in
// {-1, 0, 1} (|d|₂ <= √3 < 2):
//   n_i·d >= ñ_i·d - 2 e_i >= m·d - |ñ_i - m|₁ - 2 e_i.
// The computed δ = |ñ0 - m|₁ + |ñ1 - m|₁ (one rounded subtraction per component, a few
// additions) is at least max_i |ñ_i - m|₁·(1 - 2^-50); the computed m·d (at most two
// additions of terms bounded by |m|₁) is within 2^-51·|m|₁ of the exact m·d; underflow adds
// at most 2^-1075 per rounding. So fl(m·d) > δ(1 + 2^-48) + 2^-50·|m|₁ + 2·(e0 + eX + e1)
// + 2^-1060 proves n_i·d > 0 for i = 0, X, 1; the slack factors absorb the few roundings of
// the threshold. Overflow or NaN make the threshold or the dot NaN or infinite, and every
// comparison with it false.
template <int W>
[[gnu::always_inline]] inline typename Vectors<W>::Bits lane_masks(const MovingTriangleBatch& batch,
                                                                   int first_lane) {
  using Lanes = typename Vectors<W>::Lanes;
  using LaneBits = typename Vectors<W>::Bits;
  const auto& c = batch.coordinate;
  const auto at = [&](int row) { return load<W>(c[row] + first_lane); };
  // u = b - a, v = c - a at t = 0 (rows 0-8) and t = 1 (rows 9-17).
  const Lanes u0x = at(3) - at(0), u0y = at(4) - at(1), u0z = at(5) - at(2);
  const Lanes v0x = at(6) - at(0), v0y = at(7) - at(1), v0z = at(8) - at(2);
  const Lanes u1x = at(12) - at(9), u1y = at(13) - at(10), u1z = at(14) - at(11);
  const Lanes v1x = at(15) - at(9), v1y = at(16) - at(10), v1z = at(17) - at(11);
  // n0 = u0×v0, n1 = u1×v1, m = (u0×v1 + u1×v0) / 2.
  const Lanes x = 0.5 * ((u0y * v1z - u0z * v1y) + (u1y * v0z - u1z * v0y));
  const Lanes y = 0.5 * ((u0z * v1x - u0x * v1z) + (u1z * v0x - u1x * v0z));
  const Lanes z = 0.5 * ((u0x * v1y - u0y * v1x) + (u1x * v0y - u1y * v0x));
  const Lanes delta =
      l1((u0y * v0z - u0z * v0y) - x, (u0z * v0x - u0x * v0z) - y, (u0x * v0y - u0y * v0x) - z) +
      l1((u1y * v1z - u1z * v1y) - x, (u1z * v1x - u1x * v1z) - y, (u1x * v1y - u1y * v1x) - z);
  // e0 + eX + e1 = 2^-48·(|u0|₁|v0|₁ + |u0|₁|v1|₁ + |u1|₁|v0|₁ + |u1|₁|v1|₁), factored.
  const Lanes errors =
      0x1p-48 * ((l1(u0x, u0y, u0z) + l1(u1x, u1y, u1z)) * (l1(v0x, v0y, v0z) + l1(v1x, v1y, v1z)));
  const Lanes threshold = delta * (1 + 0x1p-48) + 0x1p-50 * l1(x, y, z) + 2 * errors + 0x1p-1060;
  const Lanes negative_threshold = -threshold;
  // Dot products in the order of kDirections, each as at most two additions.
  const Lanes xy = x + y, x_y = x - y;
  const Lanes dots[13] = {x,     y,     z,      xy,     x_y,     x + z,  x - z,
                          y + z, y - z, xy + z, xy - z, x_y + z, x_y - z};
  LaneBits mask = {};
  for (int j = 0; j < 13; ++j) {
    mask |= (dots[j] > threshold) & (std::int64_t{1} << (2 * j));
    mask |= (dots[j] < negative_threshold) & (std::int64_t{1} << (2 * j + 1));
  }
  return mask;
}

// The and of the masks of lanes [first, end) (a multiple of W of them, at least W), as a
// scalar: no vector crosses the call into the functions built for wider instruction sets.
template <int W>
[[gnu::always_inline]] inline std::int64_t lanes_mask(const MovingTriangleBatch& batch, int first,
                                                      int end) {
  typename Vectors<W>::Bits masks = lane_masks<W>(batch, first);
  for (first += W; first < end; first += W) masks &= lane_masks<W>(batch, first);
  std::int64_t all = kAllDirections;
  for (int i = 0; i < W; ++i) all &= masks[i];
  return all;
}

template <int W>
[[gnu::always_inline]] inline DirectionMask batch_mask(const MovingTriangleBatch& batch) {
  return static_cast<DirectionMask>(lanes_mask<W>(batch, 0, batch.padded_count()));
}

// The same operations on four lanes at a time: every lane's result is bit for bit that of
// the two-lane code (no FMA: the target adds only AVX2, so nothing is contracted).
[[gnu::target("avx2")]] DirectionMask batch_mask_avx2(const MovingTriangleBatch& batch) {
  return batch_mask<4>(batch);
}

// Eight lanes at a time, and the last four (a batch is padded to a multiple of four
// lanes) as in batch_mask_avx2. The same operations per lane, so bit for bit the same
// masks (-ffp-contract=off keeps a·b + c two roundings where AVX-512 offers an FMA).
// (Packing the comparisons' mask registers into words instead of lane bits was slower.)
[[gnu::target("avx512f,avx512dq,avx2")]] DirectionMask batch_mask_avx512(
    const MovingTriangleBatch& batch) {
  const int lanes = batch.padded_count(), wide = lanes & ~7;
  std::int64_t all = kAllDirections;
  if (wide > 0) all &= lanes_mask<8>(batch, 0, wide);
  if (wide < lanes) all &= lanes_mask<4>(batch, wide, lanes);
  return static_cast<DirectionMask>(all);
}

}  // namespace

namespace detail {

DirectionMask direction_mask_two_lanes(const MovingTriangleBatch& batch) {
  return batch_mask<2>(batch);
}

DirectionMask direction_mask_four_lanes(const MovingTriangleBatch& batch) {
  return batch_mask_avx2(batch);
}

DirectionMask direction_mask_eight_lanes(const MovingTriangleBatch& batch) {
  return batch_mask_avx512(batch);
}

bool direction_mask_has_eight_lanes() {
  return lanes::has_avx512();
}

bool direction_mask_has_four_lanes() {
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

DirectionMask direction_mask(const MovingTriangleBatch& batch) {
  if (batch.count == 0) return kAllDirections;
  if (lanes::has_avx512()) return detail::direction_mask_eight_lanes(batch);
  return lanes::has_avx2() ? detail::direction_mask_four_lanes(batch)
                           : detail::direction_mask_two_lanes(batch);
}

DirectionMask direction_mask(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                             const Vec3& b1, const Vec3& c1) {
  MovingTriangleBatch batch;
  batch.add(a0.data(), b0.data(), c0.data(), a1.data(), b1.data(), c1.data());
  batch.pad();
  return direction_mask(batch);
}

}  // namespace tailor

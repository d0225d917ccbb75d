#pragma once
/// @file
/// The plane-side filter of a candidate triangle pair: Tang, Manocha & Tong's (2010)
/// non-penetration filter applied to the pair as a whole, before any feature pair is made.
///
/// For a triangle P = (a, b, c) and a point q, all moving linearly over the step, the
/// coplanarity function f_q(t) = n(t)·(q(t) - a(t)), n = (b - a) × (c - a), is a cubic in
/// t whose Bernstein coefficients are (with u = b - a, v = c - a, w = q - a at t = 0 and 1)
///   β0 = n0·w0,  3β1 = n0·w1 + m·w0,  3β2 = n1·w0 + m·w1,  β3 = n1·w1,
///   n0 = u0 × v0,  n1 = u1 × v1,  m = u0 × v1 + u1 × v0
/// (the blossom of the trilinear det(u, v, w); docs/design.md §3). When all four are
/// certainly positive, f_q > 0 on [0, 1] (the convex-hull property): q stays strictly on
/// the positive side of P's plane for the whole step, and n(t) never vanishes.
///
/// What that proves (each a statement about every t in [0, 1]):
/// - Vertex q never touches P (the DNF filter's verdict for the pair (q, P)).
/// - A segment whose two endpoints are strictly on one side stays strictly on that side
///   (the signed distance to a plane is affine in the point): it touches no segment of P,
///   since P's edges lie in P's plane.
/// - A triangle Q whose three corners are strictly on one side of P's plane touches P
///   nowhere: no vertex-face or edge-edge pair between P and Q can collide, so the
///   candidate triangle pair (P, Q) is dropped whole ("separated").
/// Both orders are tested (Q's corners against P's plane and P's corners against Q's),
/// so each pair gets six corner sides, from which the low level drops the vertex-face
/// and edge-edge pairs that these facts exclude.
///
/// Certified evaluation, in double, eight pairs per AVX-512 vector. Every difference of
/// two input coordinates rounds once; along any term of a coefficient there are at most
/// ten roundings (3β1: three differences, the product, the cross product's difference,
/// the sum of two cross products, the product with w, two additions of the dot product,
/// the final sum), so the error is below γ10 = 10u/(1 - 10u) (u = 2^-53) times the sum of
/// the absolute values of the coefficient's monomials, and that sum is at most
/// S·W with S = (|u0|₁ + |u1|₁)(|v0|₁ + |v1|₁) and W = max(|w0|∞, |w1|∞). The test uses
/// the bound 2^-49·S·W + 2^-600 for all four coefficients: 16u·S·W covers γ10 times the
/// exact S·W even after the roundings of S and W themselves, and 2^-600 covers every
/// absolute error of an underflowing product, since the lanes whose |u|₁ sums or W exceed
/// 2^200 are never certified (then no product of three factors overflows, and an
/// underflow's 2^-1075 is multiplied by at most 2^200 twice). A coordinate beyond that
/// range, or a difference that overflows, only leaves its pairs to the later filters.
/// One crude bound for all four coefficients costs a little certainty for corners within
/// about 10^-14 of the relative size of the triangle from its plane, which then go to the
/// per-pair filters; nothing is ever dropped on an uncertain sign.

#include <cstdint>
#include <span>

#include "tailor/culling/triangle_pair.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor {

/// The six corner sides of a candidate triangle pair (first, second): bit k (0-2) for
/// corner k of the second face against the plane of the first, bit 3 + k for corner k of
/// the first face against the plane of the second. A set bit of `above` (`below`) means
/// that the corner is certainly strictly on the positive (negative) side of that moving
/// plane during the whole step (the plane's normal is (b - a) × (c - a) in the face's
/// corner order); a corner with neither bit may cross it, or could not be certified.
struct TrianglePairSides {
  /// Corners certainly strictly above the other face's plane (bits as above).
  std::uint8_t above = 0;
  /// Corners certainly strictly below the other face's plane.
  std::uint8_t below = 0;
  /// 1 when a fixed direction keeps the two faces apart over the whole step
  /// (step_separating_direction.hpp): no feature pair of theirs can touch.
  std::uint8_t apart = 0;

  /// Bit of corner k of the second face against the first face's plane.
  static constexpr int second_corner(int k) { return k; }
  /// Bit of corner k of the first face against the second face's plane.
  static constexpr int first_corner(int k) { return 3 + k; }

  /// Whether all three corners of one face are on one side of the other's plane: no
  /// feature pair of the two faces can touch.
  bool separated() const { return apart != 0 || separated_by_plane(); }
  /// Whether all three corners of one face are on one side of the other's plane.
  bool separated_by_plane() const {
    return (above & 7u) == 7u || (below & 7u) == 7u || (above >> 3) == 7u || (below >> 3) == 7u;
  }
  /// Whether the corner of `bit` never meets the other face's plane.
  bool corner_off_plane(int bit) const { return (((above | below) >> bit) & 1u) != 0; }
  /// Whether the segment between the corners of bits `i` and `j` (of one face) never
  /// meets the other face's plane: both on the same side.
  bool segment_off_plane(int i, int j) const {
    return ((((above >> i) & (above >> j)) | ((below >> i) & (below >> j))) & 1u) != 0;
  }
};

/// The corner sides of each pair of `pairs` (faces of `faces`, vertices moving from `x0`
/// to `x1`) into `sides` (of the same size). Sequential (call it from parallel tasks on
/// parts of a list); the result does not depend on the processor's vector width.
void triangle_pair_sides(const FaceArray& faces, const Positions& x0, const Positions& x1,
                         std::span<const TrianglePair> pairs, std::span<TrianglePairSides> sides);

namespace detail {
/// triangle_pair_sides with two lanes per vector (SSE2, any x86-64 processor) and with
/// the widest build this processor runs; exposed so that a test can check they agree.
void triangle_pair_sides_two_lanes(const FaceArray& faces, const Positions& x0, const Positions& x1,
                                   std::span<const TrianglePair> pairs,
                                   std::span<TrianglePairSides> sides);
}  // namespace detail

}  // namespace tailor

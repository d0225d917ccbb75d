#pragma once
/// @file
/// The plane through three linearly moving points, and the side of it other moving
/// points keep over a step: many points against one plane at a fraction of the cost of
/// calling coplanarity_sign() for each.

#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {

/// Plane through `a(t), q(t), r(t)`; side(p) is the exact sign of det(p-a, q-a, r-a)(t)
/// over the step, i.e. coplanarity_sign(a, p, q, r), for every input.
///
/// Why it is the same test. coplanarity_bernstein_double() evaluates the four blossom
/// values as sums of dot products of its first difference vector with cross products of
/// the other two; here the first is u = p - a and the crossed pair is v = q - a,
/// w = r - a, which do not depend on p: the cross products are computed once, and side()
/// evaluates each value with the same expressions (same rounding count, at most 10
/// roundings along any term). Its error bound is 16u times a magnitude no smaller than
/// that function's: the sum of |u_k| |v_l w_m| over the terms is at most
/// ‖u‖₁ · 2‖v‖∞‖w‖∞ per determinant, so the bound only widens (and the slack between
/// 10u and 16u covers the few roundings of the norms). The same range guard applies. A
/// coefficient the bound cannot decide, or an input out of the guarded range, falls back
/// to coplanarity_sign() itself, which decides exactly.
class MovingPlane {
 public:
  MovingPlane() = default;
  /// The plane through `a`, `q`, `r`, each moving linearly from its t0 to its t1 position.
  MovingPlane(const Vec3& a_t0, const Vec3& q_t0, const Vec3& r_t0, const Vec3& a_t1,
              const Vec3& q_t1, const Vec3& r_t1);

  /// Sign of det(p-a, q-a, r-a) over the whole step (positive: p stays on the side the
  /// normal (q-a)×(r-a) points to).
  StepSign side(const Vec3& p_t0, const Vec3& p_t1) const;

 private:
  Vec3 m_a0 = Vec3::Zero(), m_q0 = Vec3::Zero(), m_r0 = Vec3::Zero();
  Vec3 m_a1 = Vec3::Zero(), m_q1 = Vec3::Zero(), m_r1 = Vec3::Zero();
  bool m_in_range = true;
  // v_i × w_j (v = q - a, w = r - a), and 2^-49 · 2‖v_i‖∞‖w_j‖∞ for the error bounds.
  Vec3 m_c00 = Vec3::Zero(), m_c11 = Vec3::Zero(), m_c01 = Vec3::Zero(), m_c10 = Vec3::Zero();
  double m_e00 = 0, m_e11 = 0, m_e01 = 0, m_e10 = 0;
};

}  // namespace tailor

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
/// Why it is the same test. coplanarity_bernstein_double() evaluates the blossom values
/// from the cross products of its second and third difference vectors dotted with the
/// first; here the first is p - a and the crossed pair is (q - a, r - a), which do not
/// depend on p: they are computed once, in the same expression order, and side() finishes
/// each Bernstein coefficient and its error bound exactly as that function does (same
/// rounding count, same 2^-49 bound, same range guard). A coefficient the bound cannot
/// decide, or an input out of the guarded range, falls back to coplanarity_sign() itself.
class MovingPlane {
 public:
  MovingPlane() = default;
  MovingPlane(const Vec3& a_t0, const Vec3& q_t0, const Vec3& r_t0, const Vec3& a_t1,
              const Vec3& q_t1, const Vec3& r_t1);

  /// Sign of det(p-a, q-a, r-a) over the whole step (positive: p stays on the side the
  /// normal (q-a)×(r-a) points to).
  StepSign side(const Vec3& p_t0, const Vec3& p_t1) const;

 private:
  Vec3 m_a0 = Vec3::Zero(), m_q0 = Vec3::Zero(), m_r0 = Vec3::Zero();
  Vec3 m_a1 = Vec3::Zero(), m_q1 = Vec3::Zero(), m_r1 = Vec3::Zero();
  bool m_in_range = true;
  // v_i × w_j and the same on absolute values, v = q - a, w = r - a.
  double m_c00[3]{}, m_c11[3]{}, m_c01[3]{}, m_c10[3]{};
  double m_m00[3]{}, m_m11[3]{}, m_m01[3]{}, m_m10[3]{};
};

}  // namespace tailor

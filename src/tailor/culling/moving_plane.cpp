#include "tailor/culling/moving_plane.hpp"

#include <cmath>

namespace tailor {
namespace {

// The guarded range of coplanarity_bernstein_double(): zero or magnitude in [2^-250, 2^250].
bool in_guarded_range(const Vec3& x) {
  constexpr double kLo = 0x1p-250, kHi = 0x1p250;
  bool ok = true;
  for (int k = 0; k < 3; ++k) {
    const double m = std::fabs(x[k]);
    ok &= (m == 0.0) | ((m >= kLo) & (m <= kHi));
  }
  return ok;
}

// p × q with the component expressions of coplanarity_bernstein_double().
Vec3 cross(const Vec3& p, const Vec3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}

double dot(const Vec3& p, const Vec3& q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

}  // namespace

MovingPlane::MovingPlane(const Vec3& a_t0, const Vec3& q_t0, const Vec3& r_t0, const Vec3& a_t1,
                         const Vec3& q_t1, const Vec3& r_t1)
    : m_a0(a_t0), m_q0(q_t0), m_r0(r_t0), m_a1(a_t1), m_q1(q_t1), m_r1(r_t1) {
  const Vec3 v0 = q_t0 - a_t0, w0 = r_t0 - a_t0, v1 = q_t1 - a_t1, w1 = r_t1 - a_t1;
  m_in_range =
      in_guarded_range(v0) && in_guarded_range(w0) && in_guarded_range(v1) && in_guarded_range(w1);
  m_c00 = cross(v0, w0);
  m_c11 = cross(v1, w1);
  m_c01 = cross(v0, w1);
  m_c10 = cross(v1, w0);
  const double nv0 = v0.cwiseAbs().maxCoeff(), nv1 = v1.cwiseAbs().maxCoeff();
  const double nw0 = w0.cwiseAbs().maxCoeff(), nw1 = w1.cwiseAbs().maxCoeff();
  m_e00 = 0x1p-48 * (nv0 * nw0);
  m_e11 = 0x1p-48 * (nv1 * nw1);
  m_e01 = 0x1p-48 * (nv0 * nw1);
  m_e10 = 0x1p-48 * (nv1 * nw0);
}

StepSign MovingPlane::side(const Vec3& p_t0, const Vec3& p_t1) const {
  const Vec3 u0 = p_t0 - m_a0, u1 = p_t1 - m_a1;
  if (m_in_range && in_guarded_range(u0) && in_guarded_range(u1)) {
    // The expressions of coplanarity_bernstein_double(), term for term.
    const double value[4] = {dot(u0, m_c00), dot(u1, m_c00) + dot(u0, m_c10) + dot(u0, m_c01),
                             dot(u0, m_c11) + dot(u1, m_c01) + dot(u1, m_c10), dot(u1, m_c11)};
    const double n0 = std::fabs(u0[0]) + std::fabs(u0[1]) + std::fabs(u0[2]);
    const double n1 = std::fabs(u1[0]) + std::fabs(u1[1]) + std::fabs(u1[2]);
    const double bound[4] = {n0 * m_e00, n1 * m_e00 + n0 * (m_e10 + m_e01),
                             n0 * m_e11 + n1 * (m_e01 + m_e10), n1 * m_e11};
    bool positive = false, negative = false, undecided = false;
    for (int i = 0; i < 4; ++i) {
      if (bound[i] == 0.0) return StepSign::mixed;  // every term is exactly zero
      positive |= value[i] > bound[i];
      negative |= value[i] < -bound[i];
      undecided |= !(value[i] > bound[i]) && !(value[i] < -bound[i]);
    }
    if (positive && negative) return StepSign::mixed;
    if (!undecided) return positive ? StepSign::positive : StepSign::negative;
  }
  return coplanarity_sign({m_a0, p_t0, m_q0, m_r0}, {m_a1, p_t1, m_q1, m_r1});
}

}  // namespace tailor

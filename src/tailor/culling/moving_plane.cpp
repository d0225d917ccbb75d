#include "tailor/culling/moving_plane.hpp"

#include <cmath>

namespace tailor {
namespace {

// The guarded range of coplanarity_bernstein_double(): zero or magnitude in [2^-250, 2^250].
bool in_guarded_range(const double* x) {
  constexpr double kLo = 0x1p-250, kHi = 0x1p250;
  bool ok = true;
  for (int k = 0; k < 3; ++k) {
    const double m = std::fabs(x[k]);
    ok &= (m == 0.0) | ((m >= kLo) & (m <= kHi));
  }
  return ok;
}

void cross(const double* p, const double* q, double* r) {
  r[0] = p[1] * q[2] - p[2] * q[1];
  r[1] = p[2] * q[0] - p[0] * q[2];
  r[2] = p[0] * q[1] - p[1] * q[0];
}

void cross_abs(const double* p, const double* q, double* r) {
  r[0] = std::fabs(p[1] * q[2]) + std::fabs(p[2] * q[1]);
  r[1] = std::fabs(p[2] * q[0]) + std::fabs(p[0] * q[2]);
  r[2] = std::fabs(p[0] * q[1]) + std::fabs(p[1] * q[0]);
}

double dot(const double* p, const double* q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

double dot_abs(const double* p, const double* q) {
  return std::fabs(p[0]) * q[0] + std::fabs(p[1]) * q[1] + std::fabs(p[2]) * q[2];
}

}  // namespace

MovingPlane::MovingPlane(const Vec3& a_t0, const Vec3& q_t0, const Vec3& r_t0, const Vec3& a_t1,
                         const Vec3& q_t1, const Vec3& r_t1)
    : m_a0(a_t0), m_q0(q_t0), m_r0(r_t0), m_a1(a_t1), m_q1(q_t1), m_r1(r_t1) {
  double v0[3], w0[3], v1[3], w1[3];
  for (int k = 0; k < 3; ++k) {
    v0[k] = q_t0[k] - a_t0[k];
    w0[k] = r_t0[k] - a_t0[k];
    v1[k] = q_t1[k] - a_t1[k];
    w1[k] = r_t1[k] - a_t1[k];
  }
  m_in_range =
      in_guarded_range(v0) && in_guarded_range(w0) && in_guarded_range(v1) && in_guarded_range(w1);
  cross(v0, w0, m_c00);
  cross(v1, w1, m_c11);
  cross(v0, w1, m_c01);
  cross(v1, w0, m_c10);
  cross_abs(v0, w0, m_m00);
  cross_abs(v1, w1, m_m11);
  cross_abs(v0, w1, m_m01);
  cross_abs(v1, w0, m_m10);
}

StepSign MovingPlane::side(const Vec3& p_t0, const Vec3& p_t1) const {
  double u0[3], u1[3];
  for (int k = 0; k < 3; ++k) {
    u0[k] = p_t0[k] - m_a0[k];
    u1[k] = p_t1[k] - m_a1[k];
  }
  if (m_in_range && in_guarded_range(u0) && in_guarded_range(u1)) {
    // The expressions of coplanarity_bernstein_double(), term for term.
    const double value[4] = {dot(u0, m_c00), dot(u1, m_c00) + dot(u0, m_c10) + dot(u0, m_c01),
                             dot(u0, m_c11) + dot(u1, m_c01) + dot(u1, m_c10), dot(u1, m_c11)};
    const double bound[4] = {
        0x1p-49 * dot_abs(u0, m_m00),
        0x1p-49 * (dot_abs(u1, m_m00) + dot_abs(u0, m_m10) + dot_abs(u0, m_m01)),
        0x1p-49 * (dot_abs(u0, m_m11) + dot_abs(u1, m_m01) + dot_abs(u1, m_m10)),
        0x1p-49 * dot_abs(u1, m_m11)};
    bool positive = false, negative = false, undecided = false;
    for (int i = 0; i < 4; ++i) {
      if (bound[i] == 0.0) return StepSign::mixed;  // the coefficient is exactly zero
      positive |= value[i] > bound[i];
      negative |= value[i] < -bound[i];
      undecided |= !(value[i] > bound[i]) && !(value[i] < -bound[i]);
    }
    if (positive && negative) return StepSign::mixed;
    if (!undecided) return positive ? StepSign::positive : StepSign::negative;
  }
  return coplanarity_sign(m_a0, p_t0, m_q0, m_r0, m_a1, p_t1, m_q1, m_r1);
}

}  // namespace tailor

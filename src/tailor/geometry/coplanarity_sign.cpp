#include "tailor/geometry/coplanarity_sign.hpp"

#include <gmpxx.h>

#include <array>
#include <stdexcept>

namespace tailor::detail {

namespace {

using Q3 = std::array<mpq_class, 3>;

Q3 difference(const Vec3& x, const Vec3& y) {
  Q3 r;
  for (int k = 0; k < 3; ++k) r[k] = mpq_class(x[k]) - mpq_class(y[k]);
  return r;
}

mpq_class det(const Q3& u, const Q3& v, const Q3& w) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

}  // namespace

int coplanarity_coefficient_sign_exact(int index, const Vec3& a_t0, const Vec3& b_t0,
                                       const Vec3& c_t0, const Vec3& d_t0, const Vec3& a_t1,
                                       const Vec3& b_t1, const Vec3& c_t1, const Vec3& d_t1) {
  for (const Vec3* x : {&a_t0, &b_t0, &c_t0, &d_t0, &a_t1, &b_t1, &c_t1, &d_t1}) {
    if (!x->allFinite()) throw std::invalid_argument("coplanarity_sign: non-finite coordinate");
  }
  const Q3 u0 = difference(b_t0, a_t0), v0 = difference(c_t0, a_t0), w0 = difference(d_t0, a_t0);
  const Q3 u1 = difference(b_t1, a_t1), v1 = difference(c_t1, a_t1), w1 = difference(d_t1, a_t1);
  mpq_class value;
  switch (index) {
    case 0:
      value = det(u0, v0, w0);
      break;
    case 1:
      value = det(u1, v0, w0) + det(u0, v1, w0) + det(u0, v0, w1);
      break;
    case 2:
      value = det(u0, v1, w1) + det(u1, v0, w1) + det(u1, v1, w0);
      break;
    default:
      value = det(u1, v1, w1);
      break;
  }
  const int s = sgn(value);
  return (s > 0) - (s < 0);
}

}  // namespace tailor::detail

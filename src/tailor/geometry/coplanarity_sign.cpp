#include "tailor/geometry/coplanarity_sign.hpp"

#include <gmpxx.h>

#include <array>
#include <stdexcept>

#include "tailor/geometry/common_scale_integers.hpp"
#include "tailor/geometry/fixed_int.hpp"

namespace tailor::detail {

namespace {

/// The coefficient `index` (up to its positive factor) from the 18 differences.
template <class Number, class Vector>
Number coefficient(int index, const Vector& u0, const Vector& v0, const Vector& w0,
                   const Vector& u1, const Vector& v1, const Vector& w1) {
  auto det = [](const Vector& u, const Vector& v,
                const Vector& w) -> Number {  // a value, not a GMP expression of temporaries
    return u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
           u[2] * (v[0] * w[1] - v[1] * w[0]);
  };
  switch (index) {
    case 0:
      return det(u0, v0, w0);
    case 1:
      return det(u1, v0, w0) + det(u0, v1, w0) + det(u0, v0, w1);
    case 2:
      return det(u0, v1, w1) + det(u1, v0, w1) + det(u1, v1, w0);
    default:
      return det(u1, v1, w1);
  }
}

/// Exact sign with 2048-bit stack integers: every coordinate times 2^-(lowest exponent)
/// is an integer, and a common positive scale does not change the sign. Throws
/// CapacityExceeded when the coordinates span too many bits (products of three
/// differences must fit).
int sign_fixed(int index, const std::array<const Vec3*, 8>& x) {
  using Z = FixedInt<32>;
  const auto value = common_scale_integers<Z>(x);
  using V = std::array<Z, 3>;
  auto difference = [&](int i, int j) {
    return V{value[i][0] - value[j][0], value[i][1] - value[j][1], value[i][2] - value[j][2]};
  };
  const V u0 = difference(1, 0), v0 = difference(2, 0), w0 = difference(3, 0);
  const V u1 = difference(5, 4), v1 = difference(6, 4), w1 = difference(7, 4);
  return coefficient<Z>(index, u0, v0, w0, u1, v1, w1).sign();
}

/// The same in GMP rationals, for spreads beyond the fixed size.
int sign_rational(int index, const std::array<const Vec3*, 8>& x) {
  using Q3 = std::array<mpq_class, 3>;
  auto difference = [&](int i, int j) {
    Q3 r;
    for (int k = 0; k < 3; ++k) r[k] = mpq_class((*x[i])[k]) - mpq_class((*x[j])[k]);
    return r;
  };
  const Q3 u0 = difference(1, 0), v0 = difference(2, 0), w0 = difference(3, 0);
  const Q3 u1 = difference(5, 4), v1 = difference(6, 4), w1 = difference(7, 4);
  const int s = sgn(coefficient<mpq_class>(index, u0, v0, w0, u1, v1, w1));
  return (s > 0) - (s < 0);
}

}  // namespace

int coplanarity_coefficient_sign_exact(int index, const FourPoints& at_t0,
                                       const FourPoints& at_t1) {
  const Vec3 &a_t0 = at_t0[0], &b_t0 = at_t0[1], &c_t0 = at_t0[2], &d_t0 = at_t0[3];
  const Vec3 &a_t1 = at_t1[0], &b_t1 = at_t1[1], &c_t1 = at_t1[2], &d_t1 = at_t1[3];
  const std::array<const Vec3*, 8> x{&a_t0, &b_t0, &c_t0, &d_t0, &a_t1, &b_t1, &c_t1, &d_t1};
  for (const Vec3* p : x) {
    if (!p->allFinite()) throw std::invalid_argument("coplanarity_sign: non-finite coordinate");
  }
  try {
    return sign_fixed(index, x);
  } catch (const CapacityExceeded&) {
    return sign_rational(index, x);
  }
}

}  // namespace tailor::detail

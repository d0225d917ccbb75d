#include "tailor/geometry/orientation_predicates.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tailor {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon() / 2;  // 2^-53, unit roundoff
// Shewchuk's static bounds (Robust Predicates, 1997), for the determinant computed from
// differences taken in floating point.
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;
constexpr double kOrient2dBound = (3.0 + 16.0 * kEps) * kEps;
// Underflow adds at most a few multiples of the smallest subnormal per operation; any
// margin far above that keeps the filter certified for tiny inputs.
constexpr double kUnderflowMargin = 1e-300;

/// Exact integers for doubles scaled by one common power of two (positive scaling keeps
/// every orientation sign; differences and products of integers are exact).
template <std::size_t N>
std::array<mpz_class, N> to_scaled_integers(const std::array<double, N>& values) {
  std::array<std::int64_t, N> mantissa{};
  std::array<int, N> exponent{};
  int min_exponent = std::numeric_limits<int>::max();
  for (std::size_t i = 0; i < N; ++i) {
    int e = 0;
    const double f = std::frexp(values[i], &e);  // values[i] = f * 2^e, |f| in [0.5, 1)
    mantissa[i] = static_cast<std::int64_t>(std::ldexp(f, 53));
    exponent[i] = e - 53;
    if (mantissa[i] != 0) min_exponent = std::min(min_exponent, exponent[i]);
  }
  std::array<mpz_class, N> out;
  for (std::size_t i = 0; i < N; ++i) {
    if (mantissa[i] == 0) continue;  // default-constructed mpz is 0
    mpz_set_si(out[i].get_mpz_t(), static_cast<long>(mantissa[i]));
    mpz_mul_2exp(out[i].get_mpz_t(), out[i].get_mpz_t(),
                 static_cast<mp_bitcnt_t>(exponent[i] - min_exponent));
  }
  return out;
}

}  // namespace

std::optional<int> orient3d_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a.x() - d.x(), bdx = b.x() - d.x(), cdx = c.x() - d.x();
  const double ady = a.y() - d.y(), bdy = b.y() - d.y(), cdy = c.y() - d.y();
  const double adz = a.z() - d.z(), bdz = b.z() - d.z(), cdz = c.z() - d.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  if (!std::isfinite(permanent) || !std::isfinite(det)) return std::nullopt;
  const double bound = kOrient3dBound * permanent + kUnderflowMargin;
  // Shewchuk's det is det[a-d; b-d; c-d] = -((b-a) x (c-a)) . (d-a).
  if (det > bound) return -1;
  if (-det > bound) return 1;
  return std::nullopt;  // too close to call (exactly coplanar inputs land here too)
}

std::optional<int> orient2d_filter(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double detleft = (a.x() - c.x()) * (b.y() - c.y());
  const double detright = (a.y() - c.y()) * (b.x() - c.x());
  const double det = detleft - detright;
  const double sum = std::abs(detleft) + std::abs(detright);
  if (!std::isfinite(sum) || !std::isfinite(det)) return std::nullopt;
  const double bound = kOrient2dBound * sum + kUnderflowMargin;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return std::nullopt;
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const auto v = to_scaled_integers<12>(
      {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), d.x(), d.y(), d.z()});
  const mpz_class ux = v[3] - v[0], uy = v[4] - v[1], uz = v[5] - v[2];
  const mpz_class wx = v[6] - v[0], wy = v[7] - v[1], wz = v[8] - v[2];
  const mpz_class dx = v[9] - v[0], dy = v[10] - v[1], dz = v[11] - v[2];
  const mpz_class det =
      (uy * wz - uz * wy) * dx + (uz * wx - ux * wz) * dy + (ux * wy - uy * wx) * dz;
  return sgn(det);
}

int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) {
  const auto v = to_scaled_integers<6>({a.x(), a.y(), b.x(), b.y(), c.x(), c.y()});
  const mpz_class det = (v[2] - v[0]) * (v[5] - v[1]) - (v[3] - v[1]) * (v[4] - v[0]);
  return sgn(det);
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (const auto s = orient3d_filter(a, b, c, d)) return *s;
  return orient3d_exact(a, b, c, d);
}

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  if (const auto s = orient2d_filter(a, b, c)) return *s;
  return orient2d_exact(a, b, c);
}

}  // namespace tailor

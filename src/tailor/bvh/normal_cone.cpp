#include "tailor/bvh/normal_cone.hpp"

#include <algorithm>
#include <cmath>

namespace tailor {
namespace {

// Absolute slack on every computed cosine or sine: the quantities are of order 1 and each
// comes from a few dozen roundings (under 100·2^-53 ≈ 1.1e-14 in all), far below 2^-44.
constexpr double kSlack = 0x1p-44;
// Vectors whose squared length is outside this range are not used as directions (their
// products could underflow or overflow); the cone is wide instead.
constexpr double kMinSquared = 0x1p-900, kMaxSquared = 0x1p900;

struct Bounds {
  double cos, sin;
};

// Lower bound on cos and upper bound on sin of the angle between nonzero a and b (their
// squared lengths within the guarded range).
Bounds angle_between(const Vec3& a, const Vec3& b) {
  const double lengths = std::sqrt(a.squaredNorm() * b.squaredNorm());
  return {a.dot(b) / lengths - kSlack, a.cross(b).norm() / lengths + kSlack};
}

// The cone around `axis` holding every cone of `parts` (cos bound of the widest angle,
// when each part fits within 90 degrees of the axis), or wide.
template <std::size_t N>
NormalCone verified(const Vec3& axis, const NormalCone (&parts)[N]) {
  const double squared = axis.squaredNorm();
  if (!(squared >= kMinSquared && squared <= kMaxSquared)) return NormalCone::wide();
  double cos_bound = 1;
  for (const NormalCone& part : parts) {
    const Bounds alpha = angle_between(axis, part.axis);
    if (!(alpha.cos > 0)) return NormalCone::wide();
    // angle <= α + θ_part, and cos(α + θ) = cos α cos θ - sin α sin θ is bounded below by
    // the bounds (all nonnegative) while α + θ < π.
    cos_bound = std::min(cos_bound, alpha.cos * part.cos_bound - alpha.sin * part.sin_bound);
  }
  // One slack for the rounding of the expression above, one for the normalisation of the
  // stored axis (merges assume unit axes), which turns it by a few ulps.
  cos_bound -= 2 * kSlack;
  if (!(cos_bound > 0)) return NormalCone::wide();
  return {axis / std::sqrt(squared), cos_bound,
          std::sqrt(std::max(0.0, 1 - cos_bound * cos_bound)) + kSlack};
}

double l1(const Vec3& v) {
  return std::fabs(v[0]) + std::fabs(v[1]) + std::fabs(v[2]);
}

// The three control normals of a moving triangle and their certified errors.
struct ControlNormals {
  Vec3 n[3];
  double error[3];

  explicit ControlNormals(const MovingTriangle& t) {
    using Map = Eigen::Map<const Vec3>;
    const Vec3 u0 = Map(t.b0) - Map(t.a0), v0 = Map(t.c0) - Map(t.a0);
    const Vec3 u1 = Map(t.b1) - Map(t.a1), v1 = Map(t.c1) - Map(t.a1);
    // n(t) = u(t)×v(t) has Bézier control normals n0, nX, n1 (u, v linear in t).
    n[0] = u0.cross(v0);
    n[1] = 0.5 * (u0.cross(v1) + u1.cross(v0));
    n[2] = u1.cross(v1);
    // Forward error of a cross product of rounded differences: each component is within
    // 3·2^-53·|x|₁|y|₁ (times 1 + O(2^-53)), so its 2-norm within 6·2^-53·|x|₁|y|₁;
    // 2^-48 = 32·2^-53 is a generous certified bound (1-norms bound the 2-norms).
    const double l1_u0 = l1(u0), l1_v0 = l1(v0), l1_u1 = l1(u1), l1_v1 = l1(v1);
    error[0] = 0x1p-48 * l1_u0 * l1_v0;
    error[1] = 0x1p-48 * (l1_u0 * l1_v1 + l1_u1 * l1_v0);
    error[2] = 0x1p-48 * l1_u1 * l1_v1;
  }
};

}  // namespace

NormalCone NormalCone::merged(const NormalCone& other) const {
  if (!is_under_90_degrees() || !other.is_under_90_degrees()) return wide();
  // The smallest cone holding both has half-angle (φ + θ1 + θ2)/2 around the axis turned
  // from this axis toward the other by β = (φ + θ2 - θ1)/2 (φ the angle between the
  // axes), unless one cone holds the other. cos 2β and sin 2β come from the angle sum
  // formulas; the half-angle formulas give β. Rounding only moves the axis a little:
  // verified() makes the result conservative for the axis actually computed.
  const Vec3& a1 = axis;
  const Vec3& a2 = other.axis;
  const double cos_phi = a1.dot(a2);
  const Vec3 across = a2 - cos_phi * a1;
  const double sin_phi = across.norm();
  const NormalCone parts[2] = {*this, other};
  if (!(sin_phi > 1e-9)) return verified(cos_bound <= other.cos_bound ? a1 : a2, parts);
  const double cos_diff = other.cos_bound * cos_bound + other.sin_bound * sin_bound;
  const double sin_diff = other.sin_bound * cos_bound - other.cos_bound * sin_bound;
  const double cos_2beta = cos_phi * cos_diff - sin_phi * sin_diff;
  const double sin_2beta = sin_phi * cos_diff + cos_phi * sin_diff;
  if (sin_2beta <= 0 && cos_2beta > 0) return verified(a1, parts);  // 2β <= 0: holds other
  const double clamped = std::clamp(cos_2beta, -1.0, 1.0);
  const double cos_beta = std::sqrt(0.5 * (1 + clamped));
  const double sin_beta = std::sqrt(0.5 * (1 - clamped));
  // β >= φ: the other cone holds this one.
  if (sin_beta * cos_phi - cos_beta * sin_phi >= 0) return verified(a2, parts);
  return verified(cos_beta * a1 + (sin_beta / sin_phi) * across, parts);
}

NormalCone continuous_normal_cone(std::span<const MovingTriangle> triangles) {
  // Two passes over the control normals (recomputed: cheaper than storing them).
  Vec3 sum = Vec3::Zero();
  for (const MovingTriangle& t : triangles) {
    const ControlNormals c(t);
    sum += c.n[0] + c.n[1] + c.n[2];
  }
  const double squared = sum.squaredNorm();
  if (!(squared >= kMinSquared && squared <= kMaxSquared)) return NormalCone::wide();
  const Vec3 axis = sum / std::sqrt(squared);
  // For a true normal n within `e` of the computed ñ: axis·n >= axis·ñ - e|axis| and
  // |n| <= |ñ| + e, so cos² >= (axis·ñ - e')² / (|ñ|² + 2e|ñ|₁ + e²) with e' = e(1 + 2^-50)
  // covering |axis| <= 1 + 2^-51. The few roundings of this expression and of the square
  // root are far below the final slack.
  double cos_squared = 1;
  for (const MovingTriangle& t : triangles) {
    const ControlNormals c(t);
    for (int i = 0; i < 3; ++i) {
      const double e = c.error[i] * (1 + 0x1p-50);
      const double dot = axis.dot(c.n[i]) - e;
      const double norm2 = c.n[i].squaredNorm();
      if (!(dot > 0) || !(norm2 >= kMinSquared && norm2 <= kMaxSquared)) return NormalCone::wide();
      cos_squared = std::min(cos_squared, dot * dot / (norm2 + 2 * e * l1(c.n[i]) + e * e));
    }
  }
  const double cos_bound = std::sqrt(cos_squared) - 2 * kSlack;
  if (!(cos_bound > 0)) return NormalCone::wide();
  return {axis, cos_bound, std::sqrt(std::max(0.0, 1 - cos_bound * cos_bound)) + kSlack};
}

NormalCone continuous_normal_cone(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                                  const Vec3& b1, const Vec3& c1) {
  const MovingTriangle triangle{a0.data(), b0.data(), c0.data(), a1.data(), b1.data(), c1.data()};
  return continuous_normal_cone(std::span<const MovingTriangle>(&triangle, 1));
}

}  // namespace tailor

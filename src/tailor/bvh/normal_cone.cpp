#include "tailor/bvh/normal_cone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tailor {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kHalfPi = 0.5 * std::numbers::pi;
// Angular slack added by each merge for the rounding of atan2/cos/sin and the axis
// rotation (a few ulps of an angle of order 1, with a wide margin).
constexpr double kMergeSlack = 1e-12;

// A cone around one direction `v` whose computed value has absolute error at most
// `error` (in norm): every true direction is within asin(error/|v|) of it.
NormalCone direction_cone(const Vec3& v, double error) {
  const double length = v.norm();
  if (!(length > 0) || error >= 0.5 * length) return NormalCone::wide();
  return {v / length, std::asin(error / length) * (1 + 8 * kEps) + kMergeSlack};
}

}  // namespace

NormalCone NormalCone::merged(const NormalCone& other) const {
  if (!is_under_90_degrees() || !other.is_under_90_degrees()) return wide();
  // Angle between the axes, robust for small and large angles.
  const double phi = std::atan2(axis.cross(other.axis).norm(), axis.dot(other.axis));
  if (phi + other.half_angle <= half_angle) return {axis, half_angle + kMergeSlack};
  if (phi + half_angle <= other.half_angle) return {other.axis, other.half_angle + kMergeSlack};
  const double angle = 0.5 * (phi + half_angle + other.half_angle) + kMergeSlack;
  if (angle >= kHalfPi) return wide();
  // Rotate this axis towards the other by (angle - half_angle) in their common plane.
  Vec3 toward = other.axis - axis.dot(other.axis) * axis;
  const double toward_length = toward.norm();
  if (!(toward_length > 0)) return {axis, angle};
  toward /= toward_length;
  const double rotation = angle - half_angle;
  Vec3 new_axis = std::cos(rotation) * axis + std::sin(rotation) * toward;
  new_axis.normalize();
  return {new_axis, angle + kMergeSlack};
}

NormalCone continuous_normal_cone(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                                  const Vec3& b1, const Vec3& c1) {
  const Vec3 u0 = b0 - a0, v0 = c0 - a0, u1 = b1 - a1, v1 = c1 - a1;
  // n(t) = u(t)×v(t) has Bézier control normals n0, nX, n1 (u, v linear in t).
  const Vec3 n0 = u0.cross(v0);
  const Vec3 n1 = u1.cross(v1);
  const Vec3 nx = 0.5 * (u0.cross(v1) + u1.cross(v0));
  // Forward error of a cross product of rounded differences: each component is
  // |x||y| * (a few eps); 16 eps is a generous certified bound, 2-norms included.
  const double e0 = 16 * kEps * u0.norm() * v0.norm();
  const double e1 = 16 * kEps * u1.norm() * v1.norm();
  const double ex = 16 * kEps * (u0.norm() * v1.norm() + u1.norm() * v0.norm());
  return direction_cone(n0, e0).merged(direction_cone(nx, ex)).merged(direction_cone(n1, e1));
}

}  // namespace tailor

#include "tailor/culling/view_cone.hpp"

#include <algorithm>
#include <cmath>

namespace tailor {
namespace {

// Slack on every cosine (see the header): far above the few-u rounding errors.
constexpr double kSlack = 0x1p-40;
// Below this squared length a direction is not trusted (underflow of the normalisation).
constexpr double kTinySquared = 0x1p-900;
// A cone whose cosine bound falls under this is treated as every direction.
constexpr double kMinCos = 0x1p-20;

}  // namespace

bool unit_direction(const Vec3& observer, const Vec3& point, Vec3& unit) {
  const Vec3 d = point - observer;
  const double squared = d.squaredNorm();
  if (!(squared > kTinySquared) || !std::isfinite(squared)) return false;
  unit = d / std::sqrt(squared);
  return true;
}

ViewCone view_cone_of_directions(const Vec3 (&unit)[6]) {
  const Vec3 sum = unit[0] + unit[1] + unit[2] + unit[3] + unit[4] + unit[5];
  const double length = sum.norm();
  if (!(length > 0) || !std::isfinite(length)) return {};
  ViewCone cone;
  cone.axis = sum / length;
  double min_cos = 1;
  for (const Vec3& u : unit) min_cos = std::min(min_cos, cone.axis.dot(u));
  cone.cos_half = min_cos - kSlack;
  if (!(cone.cos_half > kMinCos)) return {};
  cone.sin_half = std::min(1.0, std::sqrt(1 - cone.cos_half * cone.cos_half) * (1 + kSlack));
  cone.everything = false;
  return cone;
}

ViewCone swept_view_cone(const std::array<Vec3, 3>& triangle_t0,
                         const std::array<Vec3, 3>& triangle_t1, const Vec3& observer_t0,
                         const Vec3& observer_t1) {
  Vec3 unit[6];
  for (int k = 0; k < 3; ++k) {
    if (!unit_direction(observer_t0, triangle_t0[k], unit[k]) ||
        !unit_direction(observer_t1, triangle_t1[k], unit[3 + k]))
      return {};
  }
  return view_cone_of_directions(unit);
}

ViewCone bounding_view_cone(const ViewCone* cones, int count) {
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < count; ++i) {
    if (cones[i].everything) return {};
    sum += cones[i].axis;
  }
  const double length = sum.norm();
  if (count == 0 || !(length > 0) || !std::isfinite(length)) return {};
  ViewCone cone;
  cone.axis = sum / length;
  // cos(β + α) ≥ cos β cos α - sin β sin α with lower bounds of the cosines and upper
  // bounds of the sines (all nonnegative), β the angle from the new axis to a member's
  // axis and α the member's half-angle.
  double min_cos = 1;
  for (int i = 0; i < count; ++i) {
    const double cos_beta = cone.axis.dot(cones[i].axis) - kSlack;
    const double sin_beta = cone.axis.cross(cones[i].axis).norm() + kSlack;
    if (!(cos_beta > 0)) return {};
    min_cos = std::min(min_cos, cos_beta * cones[i].cos_half - sin_beta * cones[i].sin_half);
  }
  cone.cos_half = min_cos - kSlack;
  if (!(cone.cos_half > kMinCos)) return {};
  cone.sin_half = std::min(1.0, std::sqrt(1 - cone.cos_half * cone.cos_half) * (1 + kSlack));
  cone.everything = false;
  return cone;
}

bool view_cones_disjoint(const ViewCone& p, const ViewCone& q) {
  if (p.everything || q.everything) return false;
  // cos(angle between axes) < cos(θp + θq) = cos θp cos θq - sin θp sin θq, where the
  // right side uses lower bounds of the cosines and upper bounds of the sines.
  const double cos_axes = p.axis.dot(q.axis);
  const double cos_sum = p.cos_half * q.cos_half - p.sin_half * q.sin_half;
  return cos_axes + kSlack < cos_sum - kSlack;
}

}  // namespace tailor

#pragma once
/// @file
/// Continuous normal cones (Tang et al., ICCD 2009; docs/design.md §2).

#include <numbers>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A cone of directions: every direction within `half_angle` of the unit `axis`. A cone
/// of half-angle π/2 or more bounds nothing useful and is stored as wide().
struct NormalCone {
  Vec3 axis = Vec3::UnitZ();
  double half_angle = std::numbers::pi;

  /// The cone that bounds no direction set (cannot certify anything).
  static NormalCone wide() { return {}; }
  /// True when every direction in the cone has a strictly positive dot with the axis.
  bool is_under_90_degrees() const { return half_angle < 0.5 * std::numbers::pi; }

  /// The smallest cone (up to rounding, always conservative) holding this one and `other`.
  NormalCone merged(const NormalCone& other) const;
};

/// Conservative continuous normal cone of a triangle moving linearly from `(a0, b0, c0)`
/// to `(a1, b1, c1)`: it holds the control normals n0, nX, n1 of the quadratic Bézier
/// normal n(t) = (b-a)×(c-a), so it holds n(t) for every t in [0, 1]. The half-angle is
/// padded by the floating-point error of each control normal, relative to its length;
/// a control normal too short to have a certain direction gives a wide cone.
NormalCone continuous_normal_cone(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                                  const Vec3& b1, const Vec3& c1);

}  // namespace tailor

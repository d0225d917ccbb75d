#pragma once
/// @file
/// Continuous normal cones (Tang et al., ICCD 2009; docs/design.md §2), computed and
/// merged without trigonometry: a cone keeps a lower bound on the cosine and an upper
/// bound on the sine of its half-angle, and every merge verifies its own result.

#include <span>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A cone of directions around `axis` (a unit vector up to rounding). Meaning, when
/// cos_bound > 0: every direction d it holds makes an angle θ_d <= θ with the axis for
/// some θ in [0, π/2) with cos θ >= cos_bound and sin θ <= sin_bound. A cone with
/// cos_bound <= 0 bounds nothing useful (wide()).
struct NormalCone {
  Vec3 axis = Vec3::UnitZ();
  double cos_bound = -1;
  double sin_bound = 1;

  /// The cone that bounds no direction set (cannot certify anything).
  static NormalCone wide() { return {}; }
  /// True when every direction in the cone has a strictly positive dot with the axis.
  bool is_under_90_degrees() const { return cos_bound > 0; }

  /// A cone holding this one and `other`: the axis that balances the two (the smallest
  /// enclosing cone, up to rounding), its bounds verified from the children, so the
  /// result is conservative whatever the rounding of the axis. Wide when the union may
  /// reach 90 degrees.
  NormalCone merged(const NormalCone& other) const;
};

/// A triangle moving linearly: its corners' coordinates at t=0 and t=1 (3 doubles each).
struct MovingTriangle {
  const double* a0;
  const double* b0;
  const double* c0;
  const double* a1;
  const double* b1;
  const double* c1;
};

/// Conservative continuous normal cone of several moving triangles at once: the axis is
/// the normalised sum of their control normals, and the bound is the widest certified
/// angle between the axis and any control normal (each widened by its floating-point
/// error). One square root and three divisions per triangle, no trigonometry.
NormalCone continuous_normal_cone(std::span<const MovingTriangle> triangles);

/// Conservative continuous normal cone of a triangle moving linearly from `(a0, b0, c0)`
/// to `(a1, b1, c1)`: it holds the control normals n0, nX, n1 of the quadratic Bézier
/// normal n(t) = (b-a)×(c-a) (Bernstein weights are nonnegative, so n(t) lies in their
/// conic hull), each widened by its certified floating-point error, so it holds n(t) for
/// every t in [0, 1]. A control normal too short for a certain direction gives a wide cone.
NormalCone continuous_normal_cone(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                                  const Vec3& b1, const Vec3& c1);

}  // namespace tailor

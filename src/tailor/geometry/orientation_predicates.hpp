#pragma once
/// @file
/// Exact orientation predicates on double inputs: a certified floating-point filter
/// (Shewchuk's static error bounds, with underflow and overflow guarded) and an exact
/// integer fallback (GMP) for the inputs the filter cannot decide.

#include <Eigen/Core>
#include <optional>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// A 2D point.
using Vec2 = Eigen::Vector2d;

/// Sign (-1, 0, 1) of `((b - a) × (c - a)) · (d - a)`, exactly: positive when `d` lies on
/// the side that the normal of the triangle `(a, b, c)` (right-hand rule) points to.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sign (-1, 0, 1) of the 2D cross product `(b - a) × (c - a)`: positive when `a, b, c`
/// turn counter-clockwise. Exact.
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

/// The floating-point filter of orient3d alone: the exact sign when the certified error
/// bound decides it, std::nullopt otherwise (exposed for tests and statistics).
std::optional<int> orient3d_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The floating-point filter of orient2d alone (see orient3d_filter).
std::optional<int> orient2d_filter(const Vec2& a, const Vec2& b, const Vec2& c);

/// orient3d evaluated in exact integer arithmetic only (no filter).
int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// orient2d evaluated in exact integer arithmetic only (no filter).
int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c);

}  // namespace tailor

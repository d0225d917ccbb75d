#pragma once
/// @file
/// Axis-aligned boxes in single precision, rounded outward: half the memory of Aabb and
/// still conservative (a FloatBox made from a double box always contains it).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tailor {

/// A float <= x, at most 3 float ulps below it (x not NaN). Branch-free rounding of a
/// value nudged down: x - |x|·2^-23 - 2^-149 is below x by more than half a float ulp
/// of x and of itself (at most |x|·2^-24·(1 + 2^-23), or 2^-150 among subnormals), so
/// rounding it to nearest cannot land above x; values beyond the float range go to the
/// largest float or to -infinity.
inline float float_at_most(double x) {
  const double nudged = x - std::fabs(x) * 0x1p-23 - 0x1p-149;
  if (nudged < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(std::min(nudged, double{std::numeric_limits<float>::max()}));
}

/// A float >= x, at most 3 float ulps above it (x not NaN).
inline float float_at_least(double x) {
  return -float_at_most(-x);
}

/// A closed box in float; empty when min > max.
struct FloatBox {
  /// Lower corner (+inf on every axis when empty).
  std::array<float, 3> min{std::numeric_limits<float>::infinity(),
                           std::numeric_limits<float>::infinity(),
                           std::numeric_limits<float>::infinity()};
  /// Upper corner (-inf on every axis when empty).
  std::array<float, 3> max{-std::numeric_limits<float>::infinity(),
                           -std::numeric_limits<float>::infinity(),
                           -std::numeric_limits<float>::infinity()};

  /// Grows the box to hold `b`.
  void extend(const FloatBox& b) {
    for (int k = 0; k < 3; ++k) {
      min[k] = b.min[k] < min[k] ? b.min[k] : min[k];
      max[k] = b.max[k] > max[k] ? b.max[k] : max[k];
    }
  }
  /// Closed-box overlap (touching boxes overlap).
  bool overlaps(const FloatBox& b) const {
    // Combined without branches (as unsigned: no bitwise operation on bools).
    unsigned meet = 1;
    for (int k = 0; k < 3; ++k) {
      meet &= unsigned{min[k] <= b.max[k]} & unsigned{b.min[k] <= max[k]};
    }
    return meet != 0;
  }
};

}  // namespace tailor

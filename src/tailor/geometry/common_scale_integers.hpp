#pragma once
/// @file
/// The coordinates of a few points as exact integers: each one times 2^-(the lowest
/// exponent among all the nonzero coordinates). A common positive scale changes no sign
/// and no root of the polynomial conditions, so the exact predicates (coplanarity_sign)
/// and the exact CCD tier compute on these integers instead of the doubles. Internal.

#include <algorithm>
#include <array>
#include <climits>
#include <cstddef>
#include <cstdint>

#include "tailor/geometry/fixed_int.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor::detail {

/// `result[i][k]` = coordinate k of `*points[i]` scaled as above, in Z (FixedInt, or the
/// exact CCD tier's BigInt: any type with Z::scaled whose default value is zero). The
/// points must be finite. Throws what Z::scaled throws when a value does not fit
/// (FixedInt: CapacityExceeded).
template <class Z, std::size_t N>
std::array<std::array<Z, 3>, N> common_scale_integers(const std::array<const Vec3*, N>& points) {
  std::uint64_t mantissa[N][3];
  int exponent[N][3];
  int lowest = INT_MAX;
  for (std::size_t i = 0; i < N; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double v = (*points[i])[k];
      mantissa[i][k] = 0;
      exponent[i][k] = 0;
      if (v == 0.0) continue;
      decompose_double(v, mantissa[i][k], exponent[i][k]);
      lowest = std::min(lowest, exponent[i][k]);
    }
  }
  std::array<std::array<Z, 3>, N> result;
  for (std::size_t i = 0; i < N; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (mantissa[i][k] == 0) continue;
      result[i][k] = Z::scaled(mantissa[i][k], exponent[i][k] - lowest, (*points[i])[k] < 0.0);
    }
  }
  return result;
}

}  // namespace tailor::detail

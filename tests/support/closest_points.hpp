#pragma once
// Closest-point distances in long double (Ericson, Real-Time Collision Detection, 5.1.5
// and 5.1.9): an oracle for the proximity predicates and the thickness CCD, independent of
// their feature conditions.

#include <Eigen/Core>
#include <algorithm>

#include "tailor/geometry/types.hpp"

namespace tailor::testing {

using L3 = Eigen::Matrix<long double, 3, 1>;

inline L3 wide(const Vec3& p) {
  return p.cast<long double>();
}

inline long double point_triangle_distance(const L3& p, const L3& a, const L3& b, const L3& c) {
  const L3 ab = b - a, ac = c - a, ap = p - a;
  const long double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const L3 bp = p - b;
  const long double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const long double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const L3 cp = p - c;
  const long double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const long double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const long double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const long double denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

inline long double segment_distance(const L3& p1, const L3& q1, const L3& p2, const L3& q2) {
  const L3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const long double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  const long double c = d1.dot(r), b = d1.dot(d2), denom = a * e - b * b;
  long double s = denom != 0 ? std::clamp((b * f - c * e) / denom, 0.0L, 1.0L) : 0.0L;
  long double t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0L, 1.0L);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0L, 1.0L);
  }
  return ((p1 + d1 * s) - (p2 + d2 * t)).norm();
}

}  // namespace tailor::testing

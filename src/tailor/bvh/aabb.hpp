#pragma once
/// @file
/// Axis-aligned bounding boxes.

#include <cmath>
#include <Eigen/Core>
#include <initializer_list>
#include <limits>
#include <span>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// An axis-aligned box; empty when min > max.
struct Aabb {
  /// Lower corner (+inf on every axis when empty).
  Eigen::Array3d min = Eigen::Array3d::Constant(std::numeric_limits<double>::infinity());
  /// Upper corner (-inf on every axis when empty).
  Eigen::Array3d max = Eigen::Array3d::Constant(-std::numeric_limits<double>::infinity());

  /// Grows the box to hold point `p`.
  void extend(const Vec3& p) {
    min = min.min(p.array());
    max = max.max(p.array());
  }
  /// Grows the box to hold box `b`.
  void extend(const Aabb& b) {
    min = min.min(b.min);
    max = max.max(b.max);
  }
  /// Closed-box overlap: boxes that touch overlap (touching can be a contact).
  bool overlaps(const Aabb& b) const { return (min <= b.max).all() && (b.min <= max).all(); }
  /// Centre (min + max) / 2; meaningless for an empty box.
  Vec3 center() const { return (0.5 * (min + max)).matrix(); }
  /// Extent max - min per axis (negative for an empty box).
  Vec3 diagonal() const { return (max - min).matrix(); }
};

/// `box` grown by `by` (≥ 0) on every side, rounded outwards: each bound moves two ulps
/// beyond the rounded sum, which is within half an ulp of the exact one.
inline Aabb grown_outwards(const Aabb& box, double by) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Aabb grown;
  for (int k = 0; k < 3; ++k) {
    grown.min[k] = std::nextafter(std::nextafter(box.min[k] - by, -kInf), -kInf);
    grown.max[k] = std::nextafter(std::nextafter(box.max[k] + by, kInf), kInf);
  }
  return grown;
}

/// Box of the given vertices at t=0 and t=1: a primitive moving linearly stays inside it
/// for the whole step.
inline Aabb swept_box(const Positions& x0, const Positions& x1,
                      std::initializer_list<Index> vertices) {
  Aabb box;
  for (Index v : vertices) {
    box.extend(Vec3(x0.row(v)));
    box.extend(Vec3(x1.row(v)));
  }
  return box;
}

/// boxes[f] = the swept box of face f, for every face, in parallel on the current task
/// arena's threads (`boxes` holds one per face). Also the floor the BVH refit is measured
/// against (`tailor bench scale`, BM_SweptBoxFloor): the time to read x0 and x1 and touch
/// every triangle once.
void swept_face_boxes(const FaceArray& faces, const Positions& x0, const Positions& x1,
                      std::span<Aabb> boxes);

}  // namespace tailor

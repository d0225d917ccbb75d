#pragma once
/// @file
/// Whether two sets moving linearly over a step can meet, from their boxes at the step's two
/// ends: a relative test, sharper than the overlap of their swept boxes.
///
/// Why it holds. A point of a triangle (or of any set of triangles) at a fixed barycentric
/// position moves linearly from x(0) to x(1), and x(0) lies in the set's box at t = 0, x(1) in
/// its box at t = 1. For two such points p (of set A) and q (of set B) and an axis k, q_k(t) -
/// p_k(t) = (1 - t)(q_k(0) - p_k(0)) + t (q_k(1) - p_k(1)). If B's box lies strictly beyond
/// A's along k at t = 0 (B.min_k > A.max_k) and again at t = 1, both terms are positive, so q_k
/// > p_k for the whole step: no point of A meets a point of B. The same with the order
/// reversed. The swept boxes (the union of both ends) are apart along k only when both end
/// boxes are apart along k in one order, so this keeps every pair the swept boxes keep, and
/// it also rejects sets that move far together: those whose swept boxes overlap only because
/// the motion is large (cloth sliding on cloth). Float boxes rounded outward keep it
/// conservative, and so does clamping beyond the float range (monotone: a strict order of
/// clamped bounds is one of the bounds themselves).

#include <cstddef>
#include <iterator>

#include "tailor/bvh/aabb.hpp"
#include "tailor/bvh/float_box.hpp"

namespace tailor {

/// Whether sets A and B, with boxes `a_start`, `b_start` at t = 0 and `a_end`, `b_end` at t = 1,
/// may meet during the step: false when one axis keeps them apart, in one order, at both ends.
/// `Box` is any box with `min[k]` and `max[k]` per axis: FloatBox (the trees), or exact double
/// bounds (the primitive boxes of the low level); or per fixed direction (DiagonalBox: the
/// argument holds for any direction, diagonal_bounds.hpp).
template <class Box>
bool may_meet_over_step(const Box& a_start, const Box& a_end, const Box& b_start,
                        const Box& b_end) {
  // Combined without branches (unsigned: the traversal runs this for every node pair, and
  // which way it goes is hard to predict).
  unsigned apart = 0;
  for (std::size_t k = 0; k < std::size(a_start.min); ++k) {
    apart |= unsigned{a_start.max[k] < b_start.min[k]} & unsigned{a_end.max[k] < b_end.min[k]};
    apart |= unsigned{b_start.max[k] < a_start.min[k]} & unsigned{b_end.max[k] < a_end.min[k]};
  }
  return apart == 0;
}

/// Boxes of a moving set at the step's start and end, in float rounded outward (half the
/// memory of double boxes): the box type of StepFeatureBoxTrees' trees, whose overlaps() is
/// may_meet_over_step().
/// Boxes grown by h / 2 each that cannot meet keep every point of one set more than h from
/// every point of the other for the whole step (along the axis that parts them, the gap
/// exceeds h at both ends).
struct StepBox {
  FloatBox start;  ///< at t = 0
  FloatBox end;    ///< at t = 1

  /// The float boxes holding the double boxes `at_start` and `at_end`.
  static StepBox holding(const Aabb& at_start, const Aabb& at_end) {
    StepBox box;
    for (int k = 0; k < 3; ++k) {
      box.start.min[k] = float_at_most(at_start.min[k]);
      box.start.max[k] = float_at_least(at_start.max[k]);
      box.end.min[k] = float_at_most(at_end.min[k]);
      box.end.max[k] = float_at_least(at_end.max[k]);
    }
    return box;
  }
  /// Grows both boxes to hold `b`'s.
  void extend(const StepBox& b) {
    start.extend(b.start);
    end.extend(b.end);
  }
  /// Whether the two sets may meet during the step (may_meet_over_step()).
  bool overlaps(const StepBox& b) const { return may_meet_over_step(start, end, b.start, b.end); }
  /// The middle of the two boxes' centres (where the tree build sorts the set).
  Vec3 center() const {
    Vec3 c;
    for (int k = 0; k < 3; ++k) {
      c[k] = 0.25 * (double{start.min[k]} + start.max[k] + end.min[k] + end.max[k]);
    }
    return c;
  }
};

}  // namespace tailor

#pragma once
/// @file
/// The conservative advancement of many vertex-face or edge-edge pairs at once, in vector
/// lanes: each lane runs ClosestDirectionAdvance::clear_from (ccd/separating_axes.hpp) for
/// one pair, with the same operations in the same order (the closest points of
/// geometry/closest_point.hpp with every case computed and the scalar's one kept), so every
/// lane computes bit for bit the time the scalar call returns. The minimum-separation CCD's search
/// calls it ~12 times for a pair that comes within h after t = 0 (cloth-ball's thickness step: 6.8
/// M calls for 560,802 pairs); one call is a chain of dependent divisions and a square root, which
/// vector lanes run for W pairs at the cost of about one (that step's exact-CCD stage 659-775 →
/// 455-474 ms on two threads, docs/thickness.md).

#include <span>

#include "tailor/ccd/separating_axes.hpp"

namespace tailor {

/// One pair's advancement from t = 0, as EarliestWithin runs it (ccd/thickness_ccd.cpp):
/// calls from the cleared time while each clears at least `narrowest` and the step is not
/// cleared to its end, at most `max_steps` calls.
struct PairAdvance {
  /// The pair's corners at t = 0 (PairShape's order: p, a, b, c or a, b, c, d).
  const FourPoints* x0 = nullptr;
  /// The same at t = 1.
  const FourPoints* x1 = nullptr;
  /// Their corner differences (CornerDifferences of x0, x1 and the pairs' shape).
  const CornerDifferences* differences = nullptr;
  /// The least advance that continues without a decision (EarliestWithin's narrowest).
  double narrowest = 0;

  /// Out: the time cleared when the advancement stopped.
  double t = 0;
  /// Out: the calls made before the last one (the last call's index).
  int step = 0;
  /// Out: what the last call returned (when has_next; otherwise `max_steps` calls each
  /// cleared at least `narrowest` and `t` is the last one's result).
  double next = 0;
  /// Out: whether the advancement stopped at a call's result (`next`).
  bool has_next = false;
  /// Out: whether it stopped on an advance shorter than `narrowest` and the pair is
  /// certainly within the witness reach at the midpoint of [next, min(1, next +
  /// narrowest)] (within_by_closest_points(): EarliestWithin's first decision there).
  bool within_after = false;
};

/// Runs the advancement of every pair of `pairs`, all of shape `shape`, against the
/// distance `h` (> 0) until it stops: a call returns 1 or more, or returns its start at the
/// first call, or clears less than `narrowest`, or `max_steps` (≥ 1) calls have been made; then
/// the witness against `witness_reach` after each stop on a short advance. The results do
/// not depend on the processor's vector width.
void advance_pairs(std::span<PairAdvance> pairs, PairShape shape, double h, double witness_reach,
                   int max_steps);

namespace detail {
/// advance_pairs with two lanes per vector (SSE2, any x86-64 processor); exposed so that a
/// test can check that every build agrees.
void advance_pairs_two_lanes(std::span<PairAdvance> pairs, PairShape shape, double h,
                             double witness_reach, int max_steps);
}  // namespace detail

}  // namespace tailor

#pragma once
/// @file
/// Minimum-separation CCD: the earliest time in a linear step at which a vertex-face or edge-edge
/// pair comes within a distance h > 0 (collisions with a thickness; h = 0 is the exact CCD of
/// ccd.hpp).
///
/// First the cheapest whole-step test, which settles most misses among pairs whose swept boxes
/// overlap (67 % on cloth-ball's thickness step): one coordinate axis keeps the two primitives more
/// than h apart for the whole step (apart_along_a_coordinate_axis(); the differences between the
/// corners are linear in t, so their ends decide; ccd/separating_axes.hpp). The detector's
/// candidate walk applies the same test to its boxes (bvh/step_boxes.hpp), so its candidates rarely
/// need it.
///
/// Then a witness that the pair is within h at t = 0 (within_by_closest_points(): the closest
/// points in double, at weights that put the exact points on the primitives, with their rounding
/// bounded): its earliest time is 0 with no search (on cloth-ball every one of the 419,425 pairs
/// within h at t = 0). Its closest points also give the advancement's first direction below.
///
/// Then conservative advancement from t = 0 (ccd/separating_axes.hpp): the closest direction u at
/// t, and the last time up to which every corner difference stays more than h |u| along u,
/// certified; repeated from there. A pair that approaches along u is cleared up to just before its
/// first time within h in a call or two, where halving the step took about twenty levels of
/// intervals. Where it stalls (an advance shorter than the narrowest interval below) the narrowest
/// interval there is decided at once, as the search would decide it; after kAdvanceSteps calls the
/// search below takes the rest of the step. Most misses end here: on cloth-ball's thickness step
/// the misses the walk left take about two calls. (A whole-step test against the face's plane or
/// the two edges' lines, from the coplanarity cubic's Bernstein coefficients, used to run first;
/// once the advancement had become this cheap, dropping it made cloth-ball's thickness step 18 %
/// faster and left the funnel's unchanged.) When the first call proves nothing, the box test below
/// on the whole step (only when the primitives move less than h relative to each other: the boxes
/// are then tight), then the distance at t = 0 decide what they can.
///
/// Then branch and bound over the rest of the step's time. On an interval I of t, every vertex lies
/// in the box x0 + I (x1 - x0), and the proximity conditions (ccd/proximity_conditions.hpp), the
/// same polynomials the static predicates decide, are evaluated in ball arithmetic over those
/// boxes: a rigorous enclosure of each condition over every configuration of I. So "certainly
/// within h" on I means the pair is within h at every t in I, and "certainly not" means at none.
/// This box test runs on the whole step (as above) and on the narrowest intervals; the intervals in
/// between are left to the Lipschitz test below, which clears more of them for less work (skipping
/// a test can only split an interval again, never drop a pair, and the narrowest intervals are
/// decided as before: the same pairs and times on cloth-ball's thickness step). Intervals are
/// visited earliest first; an undecided one is split in two until its width w satisfies L w / 2 ≤
/// 1e-6 h, where L bounds how fast the distance can change: the largest relative displacement of
/// two corners of the two primitives (max |Δp - Δa| over the face's corners a; max |Δa - Δc| over
/// an end of each edge), since any point of one primitive moves relative to any point of the other
/// by a convex combination of these, and a distance between moving sets changes no faster than its
/// points' relative speed. An undecided interval wider than that is first tried with the same
/// bound: farther than h + L w / 2 at its midpoint (balls, then exact), it is clear. At the
/// narrowest width the midpoint t_m decides, on the exact positions at t_m (balls around them
/// first, which settle the answer whenever they decide; exact rationals otherwise): if the pair is
/// within h √(1
/// + 2e-6) ≤ (1 + 1e-6) h at t_m it is reported, otherwise no t of the interval can be within h.
///
/// Guarantees: never a false negative; a pair reported has a minimum distance over the step of at
/// most (1 + 1e-6) h; its `toi` is never later than the earliest time it comes within h (every
/// earlier time was proven clear), and within max(w) ≤ 1e-6 of a time at which it is within (1 +
/// 1e-6) h. So a pair that crosses h at a useful angle gets its first time within 1e-6; one that
/// grazes h (its distance within a relative 1e-6 of h for a while) may get a time up to that while
/// earlier (cloth-ball has such pairs: 2e-4 early, with a minimum distance of 0.99999 h). A search
/// that has not ended after kMaxIntervals intervals reports the pair at the start of the interval
/// it was on (conservative, counted in `exhausted`).

#include <span>

#include "tailor/ccd/ccd.hpp"

namespace tailor {

/// What a thickness query found.
struct ThicknessResult {
  bool hit = false;        ///< the pair comes within h at some t in [0, 1]
  double toi = 1.0;        ///< when hit: a lower bound of the earliest such t (1 otherwise)
  int intervals = 0;       ///< time intervals examined
  bool exhausted = false;  ///< the search hit its cap and reported the pair conservatively
};

/// Intervals one query may examine before it reports conservatively.
inline constexpr int kMaxThicknessIntervals = 1 << 16;

/// Whether a query first tries the pair's own normal (apart_along_normals(),
/// ccd/separating_axes.hpp), or skips it because its caller has run the same test on the
/// pair already (the detector's batched filter, candidates/thickness_pair_filter.hpp).
/// Skipping changes the work: a pair the normal would have cleared goes through the search,
/// whose answer meets the same guarantees.
enum class NormalTest {
  run,   ///< try the pair's normal first
  skip,  ///< the caller has tried it
};

/// The earliest time vertex `p` comes within `h` (> 0) of the closed triangle `(a, b, c)`.
/// Throws std::invalid_argument on a non-finite input or h ≤ 0.
ThicknessResult vertex_face_ccd_within(const VertexFaceQuery& query, double h,
                                       NormalTest normal_test = NormalTest::run);

/// The earliest time the closed segments come within `h` (> 0) of each other. Throws
/// std::invalid_argument on a non-finite input or h ≤ 0.
ThicknessResult edge_edge_ccd_within(const EdgeEdgeQuery& query, double h,
                                     NormalTest normal_test = NormalTest::run);

/// vertex_face_ccd_within() of every query of `queries` into `results` (as many; throws
/// std::invalid_argument otherwise), the same results: the advancements of the pairs that
/// reach the search run several at a time in vector lanes (ccd/advance_lanes.hpp), each bit
/// for bit as one query runs it (cloth-ball's thickness step: the exact-CCD stage ~1.3×
/// faster).
void vertex_face_ccd_within(std::span<const VertexFaceQuery> queries, double h,
                            NormalTest normal_test, std::span<ThicknessResult> results);

/// edge_edge_ccd_within() of every query of `queries` into `results`, as above.
void edge_edge_ccd_within(std::span<const EdgeEdgeQuery> queries, double h, NormalTest normal_test,
                          std::span<ThicknessResult> results);

}  // namespace tailor

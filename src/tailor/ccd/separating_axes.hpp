#pragma once
/// @file
/// Certified separation of a moving vertex-face or edge-edge pair by more than a distance
/// h along one fixed direction, over a whole step or the front of it, and a witness of the
/// opposite (two points within h at one instant): the cheap tests that the
/// minimum-separation CCD (ccd/thickness_ccd.hpp) runs before and inside its search.
///
/// Why a direction proves a distance. Let the pair's four points move linearly, and let
/// d_k(t) be the differences between a corner of the second primitive and a corner of the
/// first: p's to the face's corners a - p, b - p, c - p (vertex-face, the points in the
/// order p, a, b, c), or c - a, d - a, c - b, d - b (edges ab and cd). Every vector from a
/// point of the first primitive to a point of the second is a convex combination of the
/// d_k(t) (the triangle's barycentric weights; the products (1 - σ)(1 - ρ), ... of the two
/// segment parameters). So if u · d_k(t) > h |u| for every k, every such vector w has
/// u · w > h |u|, hence |w| > h: no two points are within h at t. Each d_k(t) =
/// (1 - t) d_k(0) + t d_k(1) is linear in t, so u · d_k is too, and it exceeds a bound
/// on a whole interval when it does at both ends.
///
/// Certified evaluation: u is any vector of doubles (how it is chosen only decides how
/// sharp the test is). A difference of two coordinates rounds once and a three-term dot
/// product three more times, so u · d_k is computed within 5·2^-53 Σ|u_c| (|x_c| + |y_c|)
/// over the coordinates c of the two points x, y (bounded here by 1e-15 max|u_c| Σ(|x_c| +
/// |y_c|), whose sums are formed once per pair);
/// the interpolation in t and |u| get their own generous factors. Overflowing or
/// non-finite values only refuse (nothing is claimed).

#include <array>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Which pair the four points of a separation test form.
enum class PairShape {
  vertex_face,  ///< points p, a, b, c: vertex p and triangle abc
  edge_edge,    ///< points a, b, c, d: segments ab and cd
};

/// Whether one coordinate axis keeps the two primitives more than `h` apart for the whole
/// step (u = ± a unit axis, so |u| = 1 and only the differences round: the test asks for
/// more than h / (1 - 2^-52) of the rounded ones). A relative test: two primitives that
/// move together stay as far apart as they were, however far they move, while the swept
/// boxes the candidates come from grow with the motion.
bool apart_along_a_coordinate_axis(const FourPoints& x0, const FourPoints& x1, PairShape shape,
                                   double h);

/// Conservative advancement along the closest direction: returns t1 ≥ `t` such that no two
/// points of the pair are within `h` at any time of [t, t1] (t1 = t when nothing is
/// proven). The direction u is the one between the pair's closest points at `t` (computed
/// in double: any u is sound); the returned t1 is where the first u · d_k would reach
/// h |u|, shrunk a little and then certified at both ends as above. A pair approaching
/// along u is cleared up to just before its first time within h in one call; a pair
/// whose closest direction turns needs several, from the times returned.
double clear_along_closest_direction(const FourPoints& x0, const FourPoints& x1, PairShape shape,
                                     double t, double h);

/// The differences d_k between the pair's corners (see above) at both ends of a step, with
/// the sums Σ_c |x_c| + |y_c| their error bounds need: formed once per pair for the tests
/// along fixed directions below.
struct CornerDifferences {
  /// The differences of the pair `x0` (t = 0), `x1` (t = 1), of shape `shape`.
  CornerDifferences(const FourPoints& x0, const FourPoints& x1, PairShape shape);
  int count = 0;                       ///< differences: 3 (vertex-face) or 4
  std::array<Vec3, 4> start{};         ///< d_k at t = 0 (rounded)
  std::array<Vec3, 4> end{};           ///< d_k at t = 1 (rounded)
  std::array<double, 4> start_size{};  ///< Σ_c |x_c| + |y_c| of each d_k at t = 0
  std::array<double, 4> end_size{};    ///< the same at t = 1
};

/// Whether the pair's own normal keeps it more than `h` apart for the whole step, one way
/// or the other along it: the face's normal (vertex-face) or the cross product of the two
/// edges (edge-edge), taken at t = 0 and then at t = 1 (a fixed u each, as above). A pair
/// whose vertex stays beyond the face's plane, or whose edges stay on either side of the
/// plane they span, by more than h while the plane turns less than the gap allows: on the
/// funnel's thickness step this clears about 70 % of the candidates that are not within h,
/// at a fraction of the cost of the first advancement call (which finds the closest points).
bool apart_along_normals(const FourPoints& x0, const FourPoints& x1, const CornerDifferences& d,
                         PairShape shape, double h);

/// The weights of the closest points of a configuration, computed in double: the
/// triangle's weights of b and c (vertex-face, points p, a, b, c) or the two segment
/// parameters (edge-edge). Formed once at t = 0, they serve both the witness there and the
/// advancement's first direction.
struct ClosestWeights {
  double first = 0;   ///< b's weight, or the first segment's parameter
  double second = 0;  ///< c's weight, or the second segment's parameter
};

/// The weights of the closest points of `x` (closest_point.hpp).
ClosestWeights closest_weights(const FourPoints& x, PairShape shape);

/// Whether the closest direction of the configuration `x` (one instant; the closest weights
/// `weights` already formed) certainly keeps the pair more than `h` apart: every corner
/// difference d_k of `x` reaches beyond h |u| along it (the argument above at one instant,
/// without the interpolation in t). The proximity predicates' quick "no".
bool apart_along_closest_direction(const FourPoints& x, PairShape shape, double h,
                                   const ClosestWeights& weights);

/// clear_along_closest_direction() for repeated calls on one pair (the search calls it up
/// to hundreds of times): the corner differences at both ends and the sums their error
/// bounds need are formed once. Keeps references to `x0` and `x1`.
class ClosestDirectionAdvance {
 public:
  /// The pair of points `x0` (t = 0) and `x1` (t = 1), of shape `shape`, against `h`.
  ClosestDirectionAdvance(const FourPoints& x0, const FourPoints& x1, PairShape shape, double h)
      : ClosestDirectionAdvance(x0, x1, CornerDifferences(x0, x1, shape), shape, h) {}
  /// The same with the pair's differences `d` already formed.
  ClosestDirectionAdvance(const FourPoints& x0, const FourPoints& x1, const CornerDifferences& d,
                          PairShape shape, double h)
      : m_x0(x0), m_x1(x1), m_shape(shape), m_h(h), m_differences(d) {}
  /// t1 ≥ `t` such that no two points of the pair are within h at any time of [t, t1]
  /// (t when nothing is proven), as clear_along_closest_direction().
  double clear_from(double t) const;
  /// clear_from(0) with the closest weights of the start positions `x0` already formed
  /// (the same direction, the same result).
  double clear_from_start(const ClosestWeights& at_start) const;

 private:
  // The certified end of the interval from t that direction u clears (t when none).
  double clear_along(const Vec3& u, double t) const;

  const FourPoints& m_x0;
  const FourPoints& m_x1;
  PairShape m_shape;
  double m_h;
  CornerDifferences m_differences;
};

/// Whether two points of the pair in the configuration `x` (exact coordinates, e.g. a
/// step's start) are certainly within `h`: a witness for "within h" that needs no
/// rational. The points are the closest points computed in double, taken at weights that
/// are exactly valid (the segment parameters in [0, 1]; the triangle's two weights scaled
/// by 1 - 2^-50 and checked to sum to at most 1 - 2^-51, so the exact point with those
/// weights lies in the triangle). Forming a point from its weights rounds a few times, each
/// within 2^-53 of the coordinates' sizes, so the computed distance plus 4e-15 times the
/// sum of all |coordinates| bounds the distance of the two exact points. A difference of
/// zero, or one too small to square without underflow, refuses.
bool within_by_closest_points(const FourPoints& x, PairShape shape, double h);

/// The same witness with the closest weights of `x` already formed (closest_weights()).
bool within_by_closest_points(const FourPoints& x, PairShape shape, double h,
                              const ClosestWeights& weights);

/// The same witness at the time `t` of the step from `x0` to `x1`: the positions (1 - t) x0 +
/// t x1 are formed in double, each coordinate within 3·2^-53 (|x0| + |x1|) of the exact one,
/// and a point of either primitive, a convex combination of them, is no farther off; so the
/// bound adds 1e-15 times the sum of all |coordinates| of both frames.
bool within_by_closest_points(const FourPoints& x0, const FourPoints& x1, double t, PairShape shape,
                              double h);

}  // namespace tailor

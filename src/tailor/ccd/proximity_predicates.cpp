/// @file
/// The proximity conditions (ccd/proximity_conditions.hpp) in balls, then, when a ball
/// cannot decide, in GMP rationals.

#include "tailor/ccd/proximity_predicates.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "tailor/ccd/proximity_conditions.hpp"
#include "tailor/ccd/separating_axes.hpp"

namespace tailor {
namespace {

using detail::as;
using detail::Ball;
using detail::Truth;

void check_inputs(const FourPoints& points, double h, const char* what) {
  if (!(h >= 0) || !std::isfinite(h)) {
    throw std::invalid_argument(std::string(what) + ": the distance must be finite and >= 0");
  }
  for (const Vec3& p : points) {
    if (!p.allFinite()) throw std::invalid_argument(std::string(what) + ": non-finite coordinate");
  }
}

/// Exact conversion of the four points.
template <class T>
detail::PointSet<T> point_set(const FourPoints& q) {
  return {{as<T>(q[0]), as<T>(q[1]), as<T>(q[2]), as<T>(q[3])}};
}

/// The answer in double, when the pair is not within a hair of h: the witness (two points
/// of the pair within h, their rounding bounded) says yes; the closest direction (every
/// corner difference more than h along it, certified) says no (ccd/separating_axes.hpp).
/// Neither can contradict the exact answer; near h, or for input too small or too large to
/// bound, both refuse. On cloth-ball's proximity search at h = 1e-3 of the diagonal this
/// decides nearly every candidate at a fraction of the cost of the predicate in balls.
Truth decided_in_double(const FourPoints& q, PairShape shape, double h) {
  const ClosestWeights weights = closest_weights(q, shape);
  if (within_by_closest_points(q, shape, h, weights)) return Truth::yes;
  if (apart_along_closest_direction(q, shape, h, weights)) return Truth::no;
  return Truth::unknown;
}

/// The answer in double, then the predicate in balls, then, if undecided, in rationals.
template <class Predicate>
bool decide_within(const FourPoints& q, PairShape shape, double h, Predicate&& predicate) {
  if (const Truth quick = decided_in_double(q, shape, h); quick != Truth::unknown) {
    return quick == Truth::yes;
  }
  const Ball h_ball(h);
  const Truth certified = predicate(point_set<Ball>(q), Ball(h_ball * h_ball));
  if (certified != Truth::unknown) return certified == Truth::yes;
  const mpq_class exact_h(h);
  return predicate(point_set<mpq_class>(q), mpq_class(exact_h * exact_h)) == Truth::yes;
}

}  // namespace

bool vertex_face_within(const FourPoints& points, double h) {
  check_inputs(points, h, "vertex_face_within");
  return decide_within(points, PairShape::vertex_face, h, [](const auto& pts, const auto& h2) {
    return detail::vertex_face(pts, h2);
  });
}

bool edge_edge_within(const FourPoints& points, double h) {
  check_inputs(points, h, "edge_edge_within");
  return decide_within(points, PairShape::edge_edge, h,
                       [](const auto& pts, const auto& h2) { return detail::edge_edge(pts, h2); });
}

}  // namespace tailor

/// @file
/// Separation of a moving pair along a fixed direction (see the header for the argument).

#include "tailor/ccd/separating_axes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "tailor/geometry/closest_point.hpp"

namespace tailor {
namespace {

/// (first-primitive corner, second-primitive corner) of each difference d_k.
constexpr std::array<std::pair<int, int>, 3> kVertexToCorners{{{0, 1}, {0, 2}, {0, 3}}};
constexpr std::array<std::pair<int, int>, 4> kEndToEnd{{{0, 2}, {0, 3}, {1, 2}, {1, 3}}};

std::span<const std::pair<int, int>> differences(PairShape shape) {
  if (shape == PairShape::vertex_face) return kVertexToCorners;
  return kEndToEnd;
}

/// The positions at t (rounded; they only choose the direction).
FourPoints positions_at(const FourPoints& x0, const FourPoints& x1, double t) {
  FourPoints x;
  for (int i = 0; i < 4; ++i) x[i] = (1 - t) * x0[i] + t * x1[i];
  return x;
}

/// From the first primitive's point to the second's: p to a + first (b - a) + second (c - a)
/// (vertex-face, points p, a, b, c), or a + first (b - a) to c + second (d - c) (edge-edge).
Vec3 difference_at(const FourPoints& x, PairShape shape, double first, double second) {
  if (shape == PairShape::vertex_face) {
    return x[1] + first * (x[2] - x[1]) + second * (x[3] - x[1]) - x[0];
  }
  return (x[2] + second * (x[3] - x[2])) - (x[0] + first * (x[1] - x[0]));
}

/// From the first primitive's closest point to the second's in `x`, whose closest points
/// have the weights `w`.
Vec3 closest_direction(const FourPoints& x, PairShape shape, const ClosestWeights& w) {
  return difference_at(x, shape, w.first, w.second);
}

/// Lower bounds of u · d_k at t = 0 (`start`) and t = 1 (`end`), one per difference.
struct Projections {
  std::array<double, 4> start{}, end{};
  int count = 0;
};

/// Whether every u · d_k(t) certainly exceeds `reach` (u · d_k(t) is at least the
/// interpolation of the lower bounds, computed within 1e-15 of their sizes).
bool all_beyond(const Projections& p, double t, double reach) {
  for (int k = 0; k < p.count; ++k) {
    const double a = p.start[static_cast<std::size_t>(k)], b = p.end[static_cast<std::size_t>(k)];
    const double value = (1 - t) * a + t * b - 1e-15 * (std::fabs(a) + std::fabs(b));
    if (!(value > reach)) return false;
  }
  return true;
}

/// h |u| rounded up (`length` is |u| computed: the norm rounds a few times).
double reach(double length, double h) {
  return h * length * (1 + 1e-14);
}

/// A lower bound of u · d, where `size` is Σ_c |x_c| + |y_c| of d = y - x and `largest` is
/// max|u_c|: u · d is computed within 5·2^-53 Σ|u_c| (|x_c| + |y_c|) ≤ 1e-15 max|u_c| Σ(|x_c| +
/// |y_c|) (see the header), plus an absolute 1e-300 for underflow. -inf (nothing claimed)
/// when a product could overflow (max|u_c| Σ(|x_c| + |y_c|) above 1e300, or not a number).
double projection_at_least(const Vec3& u, double largest, const Vec3& d, double size) {
  const double bound = largest * size;
  if (!(bound <= 1e300)) return -std::numeric_limits<double>::infinity();
  return u.dot(d) - (1e-15 * bound + 1e-300);
}

/// Lower bounds of u · d_k at both ends.
Projections lower_projections(const Vec3& u, const CornerDifferences& d) {
  const double largest = u.cwiseAbs().maxCoeff();
  Projections p;
  p.count = d.count;
  for (std::size_t k = 0; k < static_cast<std::size_t>(d.count); ++k) {
    p.start[k] = projection_at_least(u, largest, d.start[k], d.start_size[k]);
    p.end[k] = projection_at_least(u, largest, d.end[k], d.end_size[k]);
  }
  return p;
}

/// Whether every u · d_k certainly exceeds `reach` at both ends, hence for the whole step
/// (each is linear in t); stops at the first that does not (most directions fail at once).
bool beyond_on_step(const Vec3& u, double reach, const CornerDifferences& d) {
  const double largest = u.cwiseAbs().maxCoeff();
  for (std::size_t k = 0; k < static_cast<std::size_t>(d.count); ++k) {
    if (!(projection_at_least(u, largest, d.start[k], d.start_size[k]) > reach) ||
        !(projection_at_least(u, largest, d.end[k], d.end_size[k]) > reach)) {
      return false;
    }
  }
  return true;
}

/// The second primitive's point minus the first's, at weights for which the exact points
/// lie on the primitives (see the header); nullopt when the weights cannot be made so.
std::optional<Vec3> witness_difference(const FourPoints& x, PairShape shape,
                                       const ClosestWeights& w) {
  if (shape == PairShape::vertex_face) {
    constexpr double kShrink = 1 - 0x1p-50;
    const double wb = std::max(0.0, w.first) * kShrink, wc = std::max(0.0, w.second) * kShrink;
    if (!(wb + wc <= 1 - 0x1p-51)) return std::nullopt;
    return difference_at(x, shape, wb, wc);
  }
  return difference_at(x, shape, std::clamp(w.first, 0.0, 1.0), std::clamp(w.second, 0.0, 1.0));
}

/// The sum of all |coordinates| of a configuration.
double size_of(const FourPoints& x) {
  double size = 0;
  for (const Vec3& point : x) size += point.cwiseAbs().sum();
  return size;
}

/// The witness on the configuration `x`, with `slack` more for how far `x` may be off.
bool witness_within(const FourPoints& x, PairShape shape, double h, double slack,
                    const ClosestWeights& weights) {
  const std::optional<Vec3> d = witness_difference(x, shape, weights);
  if (!d || !(d->cwiseAbs().maxCoeff() > 1e-140)) return false;  // none, or underflow
  return d->norm() * (1 + 1e-15) + 4e-15 * size_of(x) + slack < h;
}

}  // namespace

ClosestWeights closest_weights(const FourPoints& x, PairShape shape) {
  if (shape == PairShape::vertex_face) {
    const Vec3 w = closest_point_barycentric(x[0], x[1], x[2], x[3]);
    return {w[1], w[2]};
  }
  const auto [s, u] = closest_segment_parameters(x[0], x[1], x[2], x[3]);
  return {s, u};
}

bool within_by_closest_points(const FourPoints& x, PairShape shape, double h) {
  return within_by_closest_points(x, shape, h, closest_weights(x, shape));
}

bool within_by_closest_points(const FourPoints& x, PairShape shape, double h,
                              const ClosestWeights& weights) {
  return witness_within(x, shape, h, 0, weights);
}

bool within_by_closest_points(const FourPoints& x0, const FourPoints& x1, double t, PairShape shape,
                              double h) {
  const FourPoints x = positions_at(x0, x1, t);
  return witness_within(x, shape, h, 1e-15 * (size_of(x0) + size_of(x1)),
                        closest_weights(x, shape));
}

bool apart_along_a_coordinate_axis(const FourPoints& x0, const FourPoints& x1, PairShape shape,
                                   double h) {
  // Each difference rounds once (relative error at most 2^-53): more than h / (1 - 2^-52)
  // of the rounded one leaves more than h of the exact one.
  const double limit = h / (1 - 0x1p-52);
  for (int c = 0; c < 3; ++c) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const auto& [i, j] : differences(shape)) {
      const double d0 = x0[j][c] - x0[i][c], d1 = x1[j][c] - x1[i][c];
      low = std::min({low, d0, d1});
      high = std::max({high, d0, d1});
    }
    if (low > limit || high < -limit) return true;
  }
  return false;
}

CornerDifferences::CornerDifferences(const FourPoints& x0, const FourPoints& x1, PairShape shape) {
  for (const auto& [i, j] : differences(shape)) {
    const std::size_t k = static_cast<std::size_t>(count++);
    start[k] = x0[j] - x0[i];
    end[k] = x1[j] - x1[i];
    start_size[k] = (x0[i].cwiseAbs() + x0[j].cwiseAbs()).sum();
    end_size[k] = (x1[i].cwiseAbs() + x1[j].cwiseAbs()).sum();
  }
}

bool apart_along_normals(const FourPoints& x0, const FourPoints& x1, const CornerDifferences& d,
                         PairShape shape, double h) {
  for (const FourPoints* x : {&x0, &x1}) {
    const FourPoints& p = *x;
    const Vec3 normal = shape == PairShape::vertex_face ? (p[2] - p[1]).cross(p[3] - p[1])
                                                        : (p[1] - p[0]).cross(p[3] - p[2]);
    const double length = normal.norm();
    if (!(length > 0) || !std::isfinite(length)) continue;
    const double at_least = reach(length, h);
    if (beyond_on_step(normal, at_least, d) || beyond_on_step(-normal, at_least, d)) return true;
  }
  return false;
}

bool apart_along_closest_direction(const FourPoints& x, PairShape shape, double h,
                                   const ClosestWeights& weights) {
  const Vec3 u = closest_direction(x, shape, weights);
  const double length = u.norm();
  if (!(length > 0) || !std::isfinite(length)) return false;
  const double at_least = reach(length, h);
  const double largest = u.cwiseAbs().maxCoeff();
  for (const auto& [i, j] : differences(shape)) {
    const double size = (x[i].cwiseAbs() + x[j].cwiseAbs()).sum();
    if (!(projection_at_least(u, largest, x[j] - x[i], size) > at_least)) return false;
  }
  return true;
}

double ClosestDirectionAdvance::clear_from(double t) const {
  const FourPoints x = positions_at(m_x0, m_x1, t);
  return clear_along(closest_direction(x, m_shape, closest_weights(x, m_shape)), t);
}

double ClosestDirectionAdvance::clear_from_start(const ClosestWeights& at_start) const {
  return clear_along(closest_direction(m_x0, m_shape, at_start), 0);  // x0 is the start
}

double ClosestDirectionAdvance::clear_along(const Vec3& u, double t) const {
  const double length = u.norm();
  if (!(length > 0) || !std::isfinite(length)) return t;
  const double at_least = reach(length, m_h);
  const Projections p = lower_projections(u, m_differences);
  if (!all_beyond(p, t, at_least)) return t;
  // Where the first u · d_k would come down to h |u|; just before it, certified.
  double until = 1;
  for (int k = 0; k < p.count; ++k) {
    const double a = p.start[static_cast<std::size_t>(k)], b = p.end[static_cast<std::size_t>(k)];
    if (b < a) until = std::min(until, (a - at_least) / (a - b));
  }
  if (!(until > t)) return t;
  // Linear in t: certified at both ends, certified in between.
  if (until >= 1) return all_beyond(p, 1.0, at_least) ? 1.0 : t;
  for (const double share : {1 - 1e-9, 0.5}) {
    const double end = t + share * (until - t);
    if (all_beyond(p, end, at_least)) return end;
  }
  return t;
}

double clear_along_closest_direction(const FourPoints& x0, const FourPoints& x1, PairShape shape,
                                     double t, double h) {
  return ClosestDirectionAdvance(x0, x1, shape, h).clear_from(t);
}

}  // namespace tailor

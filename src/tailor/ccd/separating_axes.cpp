/// @file
/// Separation of a moving pair along a fixed direction (see the header for the argument).

#include "tailor/ccd/separating_axes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

namespace tailor {
namespace {

/// (first-primitive corner, second-primitive corner) of each difference d_k.
constexpr std::array<std::pair<int, int>, 3> kVertexToCorners{{{0, 1}, {0, 2}, {0, 3}}};
constexpr std::array<std::pair<int, int>, 4> kEndToEnd{{{0, 2}, {0, 3}, {1, 2}, {1, 3}}};

std::span<const std::pair<int, int>> differences(PairShape shape) {
  if (shape == PairShape::vertex_face) return kVertexToCorners;
  return kEndToEnd;
}

/// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection §5.1.5;
/// plain double: it only chooses a direction).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double scale = 1 / (va + vb + vc);
  return a + vb * scale * ab + vc * scale * ac;
}

/// The closest points of segments pq and rs (Ericson §5.1.9), as (on pq, on rs).
std::pair<Vec3, Vec3> closest_on_segments(const Vec3& p, const Vec3& q, const Vec3& r,
                                          const Vec3& s) {
  const Vec3 d1 = q - p, d2 = s - r, w = p - r;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(w);
  const auto unit = [](double x) { return std::clamp(x, 0.0, 1.0); };
  double sigma = 0, rho = 0;
  if (a <= 0 && e <= 0) return {p, r};
  if (a <= 0) {
    rho = unit(f / e);
  } else {
    const double c = d1.dot(w);
    if (e <= 0) {
      sigma = unit(-c / a);
    } else {
      const double b = d1.dot(d2), denominator = a * e - b * b;
      sigma = denominator > 0 ? unit((b * f - c * e) / denominator) : 0.0;
      rho = (b * sigma + f) / e;
      if (rho < 0) {
        rho = 0, sigma = unit(-c / a);
      } else if (rho > 1) {
        rho = 1, sigma = unit((b - c) / a);
      }
    }
  }
  return {p + sigma * d1, r + rho * d2};
}

/// The positions at t (rounded; they only choose the direction).
FourPoints positions_at(const FourPoints& x0, const FourPoints& x1, double t) {
  FourPoints x;
  for (int i = 0; i < 4; ++i) x[i] = (1 - t) * x0[i] + t * x1[i];
  return x;
}

/// From the first primitive's closest point to the second's at t.
Vec3 closest_direction(const FourPoints& x, PairShape shape) {
  if (shape == PairShape::vertex_face) return closest_on_triangle(x[0], x[1], x[2], x[3]) - x[0];
  const auto [on_first, on_second] = closest_on_segments(x[0], x[1], x[2], x[3]);
  return on_second - on_first;
}

/// Lower bounds of u · d_k at t = 0 (`start`) and t = 1 (`end`), one per difference.
struct Projections {
  std::array<double, 4> start{}, end{};
  int count = 0;
};

/// A certified lower bound of u · (y - x) (see the header: within 1e-15 Σ|u|(|x| + |y|),
/// plus an absolute 1e-300 for underflow).
double lower_dot(const Vec3& u, const Vec3& x, const Vec3& y) {
  const Vec3 d = y - x;
  const double size = u.cwiseAbs().dot(x.cwiseAbs() + y.cwiseAbs());
  return u.dot(d) - (1e-15 * size + 1e-300);
}

Projections project(const Vec3& u, const FourPoints& x0, const FourPoints& x1, PairShape shape) {
  Projections p;
  for (const auto& [i, j] : differences(shape)) {
    p.start[static_cast<std::size_t>(p.count)] = lower_dot(u, x0[i], x0[j]);
    p.end[static_cast<std::size_t>(p.count)] = lower_dot(u, x1[i], x1[j]);
    ++p.count;
  }
  return p;
}

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

}  // namespace

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

double clear_along_closest_direction(const FourPoints& x0, const FourPoints& x1, PairShape shape,
                                     double t, double h) {
  const Vec3 u = closest_direction(positions_at(x0, x1, t), shape);
  const double length = u.norm();
  if (!(length > 0) || !std::isfinite(length)) return t;
  const double reach = h * length * (1 + 1e-14);  // ≥ h |u| (the norm rounds a few times)
  const Projections p = project(u, x0, x1, shape);
  if (!all_beyond(p, t, reach)) return t;
  // Where the first u · d_k would come down to h |u|; just before it, certified.
  double until = 1;
  for (int k = 0; k < p.count; ++k) {
    const double a = p.start[static_cast<std::size_t>(k)], b = p.end[static_cast<std::size_t>(k)];
    if (b < a) until = std::min(until, (a - reach) / (a - b));
  }
  if (!(until > t)) return t;
  // Linear in t: certified at both ends, certified in between.
  if (until >= 1) return all_beyond(p, 1.0, reach) ? 1.0 : t;
  for (const double share : {1 - 1e-9, 0.5}) {
    const double end = t + share * (until - t);
    if (all_beyond(p, end, reach)) return end;
  }
  return t;
}

}  // namespace tailor

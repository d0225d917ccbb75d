/// @file
/// The proximity conditions written once over a number type: balls (certified signs, or
/// "undecided") and GMP rationals (exact).

#include "tailor/ccd/proximity_predicates.hpp"

#include <gmpxx.h>

#include <cmath>
#include <optional>
#include <stdexcept>

#include "tailor/ccd/ball.hpp"

namespace tailor {
namespace {

using detail::Ball;

/// A three-vector over a number type T (Ball or mpq_class).
template <class T>
struct V3 {
  T x, y, z;
};

template <class T>
V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// Three-valued truth: a ball may leave a sign undecided.
enum class Truth : unsigned char { no, yes, unknown };

Truth operator&&(Truth a, Truth b) {
  if (a == Truth::no || b == Truth::no) return Truth::no;
  return a == Truth::yes && b == Truth::yes ? Truth::yes : Truth::unknown;
}
Truth operator||(Truth a, Truth b) {
  if (a == Truth::yes || b == Truth::yes) return Truth::yes;
  return a == Truth::no && b == Truth::no ? Truth::no : Truth::unknown;
}

/// x ≥ 0 and x > 0, certified (a ball of radius 0 is exact).
Truth at_least_zero(const Ball& x) {
  if (x.positive() || (x.m == 0 && x.r == 0)) return Truth::yes;
  return x.negative() ? Truth::no : Truth::unknown;
}
Truth above_zero(const Ball& x) {
  if (x.positive()) return Truth::yes;
  return x.negative() || (x.m == 0 && x.r == 0) ? Truth::no : Truth::unknown;
}
Truth at_least_zero(const mpq_class& x) {
  return sgn(x) >= 0 ? Truth::yes : Truth::no;
}
Truth above_zero(const mpq_class& x) {
  return sgn(x) > 0 ? Truth::yes : Truth::no;
}

/// Point p within h of the closed segment ab (h2 = h²).
template <class T>
Truth point_segment(const V3<T>& p, const V3<T>& a, const V3<T>& b, const T& h2) {
  const V3<T> u = b - a, w = p - a, pb = p - b;
  const T ww = dot(w, w), uu = dot(u, u), wu = dot(w, u);
  const Truth ends = at_least_zero(T(h2 - ww)) || at_least_zero(T(h2 - dot(pb, pb)));
  if (ends == Truth::yes) return ends;
  const Truth between = above_zero(uu) && at_least_zero(wu) && at_least_zero(T(uu - wu)) &&
                        at_least_zero(T(h2 * uu - (ww * uu - wu * wu)));
  return ends || between;
}

template <class T>
Truth vertex_face(const V3<T>& p, const V3<T>& a, const V3<T>& b, const V3<T>& c, const T& h2) {
  const V3<T> n = cross(V3<T>(b - a), V3<T>(c - a));
  const T nn = dot(n, n);
  const T along = dot(V3<T>(p - a), n);
  const T plane_gap = along * along - h2 * nn;
  // Farther than h from the triangle's plane: farther from the triangle (most candidates).
  if (above_zero(plane_gap) == Truth::yes) return Truth::no;
  const Truth inside = above_zero(nn) && at_least_zero(dot(n, cross(V3<T>(b - a), V3<T>(p - a)))) &&
                       at_least_zero(dot(n, cross(V3<T>(c - b), V3<T>(p - b)))) &&
                       at_least_zero(dot(n, cross(V3<T>(a - c), V3<T>(p - c))));
  const Truth over_face = inside && at_least_zero(T(-plane_gap));
  if (over_face == Truth::yes) return over_face;
  return over_face || point_segment(p, a, b, h2) || point_segment(p, b, c, h2) ||
         point_segment(p, c, a, h2);
}

template <class T>
Truth edge_edge(const V3<T>& a, const V3<T>& b, const V3<T>& c, const V3<T>& d, const T& h2) {
  const V3<T> u = b - a, v = d - c, w = c - a;
  const V3<T> n = cross(u, v);
  const T nn = dot(n, n);
  const T along = dot(w, n);
  const T line_gap = along * along - h2 * nn;
  // The lines are farther than h apart (n ≠ 0 here): so are the segments (most candidates).
  if (above_zero(line_gap) == Truth::yes) return Truth::no;
  const T s = dot(cross(w, v), n), t = dot(cross(w, u), n);
  const Truth interior = above_zero(nn) && at_least_zero(s) && at_least_zero(T(nn - s)) &&
                         at_least_zero(t) && at_least_zero(T(nn - t)) &&
                         at_least_zero(T(-line_gap));
  if (interior == Truth::yes) return interior;
  return interior || point_segment(a, c, d, h2) || point_segment(b, c, d, h2) ||
         point_segment(c, a, b, h2) || point_segment(d, a, b, h2);
}

void check_inputs(const FourPoints& points, double h, const char* what) {
  if (!(h >= 0) || !std::isfinite(h)) {
    throw std::invalid_argument(std::string(what) + ": the distance must be finite and >= 0");
  }
  for (const Vec3& p : points) {
    if (!p.allFinite()) throw std::invalid_argument(std::string(what) + ": non-finite coordinate");
  }
}

template <class T>
V3<T> as(const Vec3& p) {
  return {T(p.x()), T(p.y()), T(p.z())};
}

/// The predicate in balls, then, if undecided, in rationals.
template <class Predicate>
bool decide(const FourPoints& q, double h, Predicate&& predicate) {
  const Ball h_ball(h);
  const Truth certified = predicate(as<Ball>(q[0]), as<Ball>(q[1]), as<Ball>(q[2]), as<Ball>(q[3]),
                                    Ball(h_ball * h_ball));
  if (certified != Truth::unknown) return certified == Truth::yes;
  const mpq_class exact_h(h);
  return predicate(as<mpq_class>(q[0]), as<mpq_class>(q[1]), as<mpq_class>(q[2]),
                   as<mpq_class>(q[3]), mpq_class(exact_h * exact_h)) == Truth::yes;
}

}  // namespace

bool vertex_face_within(const FourPoints& points, double h) {
  check_inputs(points, h, "vertex_face_within");
  return decide(points, h,
                [](const auto& p, const auto& a, const auto& b, const auto& c, const auto& h2) {
                  return vertex_face(p, a, b, c, h2);
                });
}

bool edge_edge_within(const FourPoints& points, double h) {
  check_inputs(points, h, "edge_edge_within");
  return decide(points, h,
                [](const auto& a, const auto& b, const auto& c, const auto& d, const auto& h2) {
                  return edge_edge(a, b, c, d, h2);
                });
}

}  // namespace tailor

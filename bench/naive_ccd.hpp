#pragma once
/// @file
/// A naive floating-point CCD baseline (NOT used by the library): the coplanarity cubic's
/// roots in [0, 1] found in plain double (monotone pieces + bisection), then an inside test
/// at each root in plain double with no tolerance. Shows what exactness costs and what it
/// buys (its false negatives / positives on the reference queries).

#include <algorithm>
#include <cmath>
#include <vector>

#include "tailor/ccd/ccd.hpp"

namespace tailor::bench {

inline Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
  return a + t * (b - a);
}

/// Roots in [0, 1] of c0 + c1 t + c2 t^2 + c3 t^3 (double, best effort).
inline std::vector<double> naive_cubic_roots(double c0, double c1, double c2, double c3) {
  auto f = [&](double t) { return ((c3 * t + c2) * t + c1) * t + c0; };
  std::vector<double> cuts{0.0};
  // Critical points: 3 c3 t^2 + 2 c2 t + c1 = 0.
  const double A = 3 * c3, B = 2 * c2, C = c1;
  if (A != 0) {
    const double disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const double s = std::sqrt(disc);
      for (double r : {(-B - s) / (2 * A), (-B + s) / (2 * A)}) {
        if (r > 0 && r < 1) cuts.push_back(r);
      }
    }
  } else if (B != 0) {
    const double r = -C / B;
    if (r > 0 && r < 1) cuts.push_back(r);
  }
  cuts.push_back(1.0);
  std::sort(cuts.begin(), cuts.end());
  std::vector<double> roots;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    double lo = cuts[i], hi = cuts[i + 1];
    double flo = f(lo), fhi = f(hi);
    if (flo == 0) {
      roots.push_back(lo);
      continue;
    }
    if (fhi == 0) {
      roots.push_back(hi);
      continue;
    }
    if ((flo < 0) == (fhi < 0)) continue;
    for (int k = 0; k < 60; ++k) {
      const double m = 0.5 * (lo + hi);
      const double fm = f(m);
      if ((fm < 0) == (flo < 0)) {
        lo = m;
        flo = fm;
      } else {
        hi = m;
      }
    }
    roots.push_back(lo);
  }
  return roots;
}

/// Monomial coefficients of the coplanarity cubic det(b-a, c-a, d-a)(t), from its values
/// at t = 0, 1/3, 2/3, 1.
template <class F>
void cubic_coefficients(F&& f, double c[4]) {
  const double f0 = f(0.0), f1 = f(1.0 / 3.0), f2 = f(2.0 / 3.0), f3 = f(1.0);
  c[0] = f0;
  c[1] = (-11 * f0 + 18 * f1 - 9 * f2 + 2 * f3) / 2;
  c[2] = (18 * f0 - 45 * f1 + 36 * f2 - 9 * f3) / 2;
  c[3] = (-9 * f0 + 27 * f1 - 27 * f2 + 9 * f3) / 2;
}

inline double det3(const Vec3& u, const Vec3& v, const Vec3& w) {
  return u.dot(v.cross(w));
}

inline bool naive_vertex_face(const VertexFaceQuery& q) {
  auto f = [&](double t) {
    const Vec3 p = lerp(q.p_t0, q.p_t1, t), a = lerp(q.a_t0, q.a_t1, t),
               b = lerp(q.b_t0, q.b_t1, t), c = lerp(q.c_t0, q.c_t1, t);
    return det3(b - a, c - a, p - a);
  };
  double k[4];
  cubic_coefficients(f, k);
  for (double t : naive_cubic_roots(k[0], k[1], k[2], k[3])) {
    const Vec3 p = lerp(q.p_t0, q.p_t1, t), a = lerp(q.a_t0, q.a_t1, t),
               b = lerp(q.b_t0, q.b_t1, t), c = lerp(q.c_t0, q.c_t1, t);
    const Vec3 n = (b - a).cross(c - a);
    if (n.squaredNorm() == 0) continue;
    if ((b - a).cross(p - a).dot(n) >= 0 && (c - b).cross(p - b).dot(n) >= 0 &&
        (a - c).cross(p - c).dot(n) >= 0) {
      return true;
    }
  }
  return false;
}

inline bool naive_edge_edge(const EdgeEdgeQuery& q) {
  auto f = [&](double t) {
    const Vec3 a = lerp(q.ea0_t0, q.ea0_t1, t), b = lerp(q.ea1_t0, q.ea1_t1, t),
               c = lerp(q.eb0_t0, q.eb0_t1, t), d = lerp(q.eb1_t0, q.eb1_t1, t);
    return det3(b - a, c - a, d - a);
  };
  double k[4];
  cubic_coefficients(f, k);
  for (double t : naive_cubic_roots(k[0], k[1], k[2], k[3])) {
    const Vec3 a = lerp(q.ea0_t0, q.ea0_t1, t), b = lerp(q.ea1_t0, q.ea1_t1, t),
               c = lerp(q.eb0_t0, q.eb0_t1, t), d = lerp(q.eb1_t0, q.eb1_t1, t);
    const Vec3 m = (b - a).cross(d - c);
    const double M = m.squaredNorm();
    if (M == 0) continue;
    const double s = (c - a).cross(d - c).dot(m), u = (c - a).cross(b - a).dot(m);
    if (s >= 0 && s <= M && u >= 0 && u <= M) return true;
  }
  return false;
}

}  // namespace tailor::bench

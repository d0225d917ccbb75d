#pragma once
// Degenerate CCD queries, shared by the ccd tests and bench/bench_ccd.cpp: every category
// that defeats floating-point CCD, built so that the degeneracy is exact in doubles, then
// optionally nudged by one ulp (one nonzero coordinate, up or down), scaled by 2^s with s in
// [-20, 20] and sometimes moved away from the origin. The generator does not know the
// answers; tests and benchmarks take them from the rational oracle.
//
// Exactness: coordinates are integers times 2^-G (G <= 40) of magnitude <= 2, the contact
// time t* is 0, 1/2 or 1 (so x1 = 2 x(t*) - x0 is exact), barycentric and segment weights
// are multiples of 1/8, and planes are spanned by small integer vectors: every sum and
// product below stays within 53 bits.

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "tailor/ccd/ccd.hpp"

namespace tailor::testing {

/// The kinds of degenerate query the generator makes.
enum class DegenerateCategory : int {
  vf_face_interior,      ///< p crosses the open face exactly at t* (or touches at t = 0, 1)
  vf_edge,               ///< p passes exactly through a point of an edge
  vf_vertex,             ///< p passes exactly through a vertex
  vf_coplanar_sliding,   ///< all four points in one fixed plane for the whole step
  vf_coplanar_affine,    ///< coplanar for the whole step in a rotating, shearing plane
  vf_flat_triangle,      ///< a zero-area triangle (collinear or coincident vertices)
  ee_interior_crossing,  ///< the edges cross exactly at interior points at t*
  ee_endpoint_on_edge,   ///< an endpoint passes exactly through the other edge
  ee_endpoint_endpoint,  ///< two endpoints meet exactly
  ee_parallel,           ///< parallel edges, becoming collinear (overlapping or touching)
  ee_coplanar_sliding,   ///< both edges in one fixed plane for the whole step
  ee_point_edge,         ///< a zero-length edge crossing the other edge
};

inline constexpr int kDegenerateCategoryCount = 12;

inline const char* degenerate_category_name(DegenerateCategory c) {
  static const char* const names[kDegenerateCategoryCount] = {"vf_face_interior",
                                                              "vf_edge",
                                                              "vf_vertex",
                                                              "vf_coplanar_sliding",
                                                              "vf_coplanar_affine",
                                                              "vf_flat_triangle",
                                                              "ee_interior_crossing",
                                                              "ee_endpoint_on_edge",
                                                              "ee_endpoint_endpoint",
                                                              "ee_parallel",
                                                              "ee_coplanar_sliding",
                                                              "ee_point_edge"};
  return names[static_cast<int>(c)];
}

/// One generated query.
struct DegenerateQuery {
  DegenerateCategory category = DegenerateCategory::vf_face_interior;
  bool vertex_face = true;
  VertexFaceQuery vf{};
  EdgeEdgeQuery ee{};
  bool nudged = false;  ///< one coordinate moved by one ulp after the construction
  int scale = 0;        ///< all coordinates were multiplied by 2^scale
};

/// Deterministic stream of degenerate queries, cycling through the categories.
class DegenerateQueryGenerator {
 public:
  explicit DegenerateQueryGenerator(std::uint64_t seed) : m_rng(seed) {}

  DegenerateQuery next() {
    DegenerateQuery q;
    q.category = static_cast<DegenerateCategory>(m_next++ % kDegenerateCategoryCount);
    m_grid = kGrids[pick(4)];
    std::array<Vec3, 8> x = build(q.category);
    q.vertex_face =
        static_cast<int>(q.category) <= static_cast<int>(DegenerateCategory::vf_flat_triangle);
    if (pick(4) == 0) {  // away from the origin: wider integers for the exact tier
      const Vec3 offset = point() * 16.0;
      for (auto& v : x) v += offset;
    }
    if (pick(2) == 0) {
      // One ulp of a nonzero coordinate (one ulp of a zero would be a subnormal: a spread
      // of ~1075 bits, the extreme-exponent case that tests and benchmarks treat apart).
      for (int attempt = 0; attempt < 24 && !q.nudged; ++attempt) {
        double& v = x[pick(8)][pick(3)];
        if (v == 0.0) continue;
        v = std::nextafter(v, pick(2) ? 1e300 : -1e300);
        q.nudged = true;
      }
    }
    q.scale = pick(41) - 20;
    for (auto& v : x) {
      for (int k = 0; k < 3; ++k) v[k] = std::ldexp(v[k], q.scale);
    }
    if (q.vertex_face) {
      q.vf = {x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
    } else {
      q.ee = {x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
    }
    return q;
  }

 private:
  static constexpr int kGrids[4] = {2, 8, 24, 40};

  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_rng); }
  /// A multiple of 2^-G in [-1, 1].
  double coordinate() {
    const std::int64_t m = std::int64_t{1} << m_grid;
    return std::ldexp(
        static_cast<double>(std::uniform_int_distribution<std::int64_t>(-m, m)(m_rng)), -m_grid);
  }
  Vec3 point() { return {coordinate(), coordinate(), coordinate()}; }
  /// A multiple of 1/8 in [lo, hi] (in eighths).
  double eighth(int lo, int hi) { return (lo + pick(hi - lo + 1)) / 8.0; }
  /// 0, 1/2 or 1.
  double contact_time() { return pick(3) * 0.5; }

  /// Start and end of a point that is at `target` at time t (the other end random).
  void through(double t, const Vec3& target, Vec3& x0, Vec3& x1) {
    if (t == 0.0) {
      x0 = target;
      x1 = point();
    } else if (t == 1.0) {
      x0 = point();
      x1 = target;
    } else {
      x0 = point();
      x1 = 2.0 * target - x0;
    }
  }
  static Vec3 at(const Vec3& x0, const Vec3& x1, double t) {
    return t == 0.0 ? x0 : (t == 1.0 ? x1 : 0.5 * (x0 + x1));
  }
  /// A small integer vector (a plane direction).
  Vec3 direction() {
    Vec3 d(pick(5) - 2, pick(5) - 2, pick(5) - 2);
    if (d.squaredNorm() == 0.0) d = {1.0, 0.0, 0.0};
    return d;
  }

  // Order of the returned points: VF p, a, b, c at t0 then t1; EE a, b, c, d at t0 then t1.
  std::array<Vec3, 8> build(DegenerateCategory c) {
    using C = DegenerateCategory;
    std::array<Vec3, 8> x;
    for (auto& v : x) v = point();
    const double t = contact_time();
    switch (c) {
      case C::vf_face_interior:
      case C::vf_edge:
      case C::vf_vertex: {
        const Vec3 a = at(x[1], x[5], t), b = at(x[2], x[6], t), cc = at(x[3], x[7], t);
        double u = 0, v = 0;
        if (c == C::vf_face_interior) {
          u = eighth(1, 5);
          v = eighth(1, 6 - static_cast<int>(u * 8));
        } else if (c == C::vf_edge) {
          const int edge = pick(3);
          const double s = eighth(1, 7);
          u = edge == 0 ? s : (edge == 1 ? 1.0 - s : 0.0);
          v = edge == 0 ? 0.0 : s;
        } else {
          const int corner = pick(3);
          u = corner == 1 ? 1.0 : 0.0;
          v = corner == 2 ? 1.0 : 0.0;
        }
        through(t, a + u * (b - a) + v * (cc - a), x[0], x[4]);
        break;
      }
      case C::vf_coplanar_sliding:
      case C::ee_coplanar_sliding: {
        // Fixed plane spanned by e1, e2 through a moving origin; points move in it.
        const Vec3 e1 = direction(), e2 = direction();
        const Vec3 o0 = point(), o1 = point();
        for (int i = 0; i < 8; ++i) {
          const Vec3& o = i < 4 ? o0 : o1;
          x[i] = o + coordinate() * e1 + coordinate() * e2;
        }
        if (pick(2) == 0) {
          // The first point passes through a point of the other primitive's first edge at
          // t; its other end stays in the plane (2 target - x0 is an affine combination).
          const Vec3 a = at(x[1], x[5], t), b = at(x[2], x[6], t);
          const Vec3 target = a + eighth(0, 8) * (b - a);
          if (t == 0.0) {
            x[0] = target;
          } else if (t == 1.0) {
            x[4] = target;
          } else {
            x[4] = 2.0 * target - x[0];
          }
        }
        break;
      }
      case C::vf_coplanar_affine: {
        // Fixed 2D coordinates in a moving frame: an affine motion keeps them coplanar.
        std::array<double, 4> X, Y;
        for (int i = 0; i < 4; ++i) {
          X[i] = coordinate();
          Y[i] = coordinate();
        }
        if (pick(2) == 0) {  // p on an edge (or vertex) of the triangle in 2D
          const double s = eighth(0, 8);
          X[0] = X[1] + s * (X[2] - X[1]);
          Y[0] = Y[1] + s * (Y[2] - Y[1]);
        }
        const Vec3 o0 = point(), o1 = point(), e10 = direction(), e11 = direction(),
                   e20 = direction(), e21 = direction();
        for (int i = 0; i < 4; ++i) {
          x[i] = o0 + X[i] * e10 + Y[i] * e20;
          x[i + 4] = o1 + X[i] * e11 + Y[i] * e21;
        }
        break;
      }
      case C::vf_flat_triangle: {
        // c on the line ab (or all three equal), at both times.
        for (int i : {1, 5}) {
          if (pick(3) == 0) {
            x[i + 1] = x[i];
            x[i + 2] = x[i];
          } else {
            x[i + 2] = x[i] + (eighth(0, 16) - 0.5) * (x[i + 1] - x[i]);
          }
        }
        const Vec3 a = at(x[1], x[5], t), b = at(x[2], x[6], t);
        through(t, a + eighth(0, 8) * (b - a), x[0], x[4]);
        break;
      }
      case C::ee_interior_crossing:
      case C::ee_endpoint_on_edge:
      case C::ee_endpoint_endpoint: {
        const Vec3 a = at(x[0], x[4], t), b = at(x[1], x[5], t);
        const double s = c == C::ee_endpoint_endpoint ? (pick(2) ? 1.0 : 0.0) : eighth(1, 7);
        const Vec3 target = a + s * (b - a);
        const Vec3 d = point();
        const double lambda = c == C::ee_interior_crossing ? eighth(1, 8) : 0.0;
        const double mu = eighth(1, 8);
        through(t, target - lambda * d, x[2], x[6]);
        through(t, target + mu * d, x[3], x[7]);
        break;
      }
      case C::ee_parallel: {
        // cd = ab shifted along ab by k and sideways by an offset that shrinks to zero
        // at t = 1 (or stays: parallel for the whole step).
        const double k = eighth(-12, 12);
        const Vec3 side = point();
        const double keep = pick(3) == 0 ? 1.0 : 0.0;
        for (int i : {0, 4}) {
          const Vec3 along = k * (x[i + 1] - x[i]);
          const Vec3 off = i == 0 ? side : keep * side;
          x[i + 2] = x[i] + along + off;
          x[i + 3] = x[i + 1] + along + off;
        }
        break;
      }
      case C::ee_point_edge: {
        const Vec3 a = at(x[0], x[4], t), b = at(x[1], x[5], t);
        through(t, a + eighth(0, 8) * (b - a), x[2], x[6]);
        x[3] = x[2];
        x[7] = x[6];
        break;
      }
    }
    return x;
  }

  std::mt19937_64 m_rng;
  int m_next = 0;
  int m_grid = 8;
};

}  // namespace tailor::testing

#pragma once
/// @file
/// Helpers shared by the ccd tests: query scaling, file lists, and an independent exact
/// static contact test (orientation predicates in rationals) used as a one-sided oracle.

#include "support/sanitized.hpp"
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tailor/ccd/ccd.hpp"
#include "tailor/ccd/ccd_double.hpp"
#include "tailor/ccd/ccd_exact.hpp"
#include "tailor/ccd/ccd_rational.hpp"

namespace tailor::test {

inline std::string data_dir() {
  return TAILOR_DATA_DIR;
}

/// Every query CSV under ccd-queries/, sorted.
inline std::vector<std::string> reference_query_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(data_dir() + "/ccd-queries")) {
    if (e.is_regular_file() && e.path().extension() == ".csv") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

using tailor::testing::sanitized;

inline Vec3 scaled(const Vec3& x, int e) {
  return {std::ldexp(x[0], e), std::ldexp(x[1], e), std::ldexp(x[2], e)};
}

inline VertexFaceQuery scaled(const VertexFaceQuery& q, int e) {
  return {scaled(q.p_t0, e), scaled(q.a_t0, e), scaled(q.b_t0, e), scaled(q.c_t0, e),
          scaled(q.p_t1, e), scaled(q.a_t1, e), scaled(q.b_t1, e), scaled(q.c_t1, e)};
}

inline EdgeEdgeQuery scaled(const EdgeEdgeQuery& q, int e) {
  return {scaled(q.ea0_t0, e), scaled(q.ea1_t0, e), scaled(q.eb0_t0, e), scaled(q.eb1_t0, e),
          scaled(q.ea0_t1, e), scaled(q.ea1_t1, e), scaled(q.eb0_t1, e), scaled(q.eb1_t1, e)};
}

/// Bitwise-equal queries.
inline bool same(const VertexFaceQuery& a, const VertexFaceQuery& b) {
  return a.p_t0 == b.p_t0 && a.a_t0 == b.a_t0 && a.b_t0 == b.b_t0 && a.c_t0 == b.c_t0 &&
         a.p_t1 == b.p_t1 && a.a_t1 == b.a_t1 && a.b_t1 == b.b_t1 && a.c_t1 == b.c_t1;
}

inline bool same(const EdgeEdgeQuery& a, const EdgeEdgeQuery& b) {
  return a.ea0_t0 == b.ea0_t0 && a.ea1_t0 == b.ea1_t0 && a.eb0_t0 == b.eb0_t0 &&
         a.eb1_t0 == b.eb1_t0 && a.ea0_t1 == b.ea0_t1 && a.ea1_t1 == b.ea1_t1 &&
         a.eb0_t1 == b.eb0_t1 && a.eb1_t1 == b.eb1_t1;
}

// ---- independent exact static oracle --------------------------------------------------

using Q3 = std::array<mpq_class, 3>;

inline Q3 at(const Vec3& x0, const Vec3& x1, const mpq_class& t) {
  Q3 r;
  for (int k = 0; k < 3; ++k) r[k] = mpq_class(x0[k]) + t * (mpq_class(x1[k]) - mpq_class(x0[k]));
  return r;
}

inline int sign(const mpq_class& x) {
  return (x > 0) - (x < 0);
}

inline Q3 sub(const Q3& a, const Q3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

inline Q3 crs(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline mpq_class dt(const Q3& a, const Q3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// p on closed segment ab: collinear and inside the bounding box (per coordinate).
inline bool on_segment(const Q3& p, const Q3& a, const Q3& b) {
  const Q3 c = crs(sub(p, a), sub(b, a));
  if (c[0] != 0 || c[1] != 0 || c[2] != 0) return false;
  for (int k = 0; k < 3; ++k) {
    if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k])) return false;
  }
  return true;
}

/// 2D orientation of (a, b, c) after dropping coordinate `drop`.
inline int orient2(const Q3& a, const Q3& b, const Q3& c, int drop) {
  const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2;
  return sign((b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]));
}

inline int dominant_axis(const Q3& n) {
  int d = 0;
  for (int k = 1; k < 3; ++k) {
    if (abs(n[k]) > abs(n[d])) d = k;
  }
  return d;
}

/// Point in closed triangle, exactly.
inline bool point_in_triangle(const Q3& p, const Q3& a, const Q3& b, const Q3& c) {
  const Q3 n = crs(sub(b, a), sub(c, a));
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
    return on_segment(p, a, b) || on_segment(p, b, c) || on_segment(p, c, a);
  }
  if (dt(n, sub(p, a)) != 0) return false;
  const int d = dominant_axis(n);
  const int s = orient2(a, b, c, d);
  return orient2(a, b, p, d) * s >= 0 && orient2(b, c, p, d) * s >= 0 &&
         orient2(c, a, p, d) * s >= 0;
}

/// Closed segments ab and cd intersect, exactly.
inline bool segments_intersect(const Q3& a, const Q3& b, const Q3& c, const Q3& d) {
  if (on_segment(a, c, d) || on_segment(b, c, d) || on_segment(c, a, b) || on_segment(d, a, b)) {
    return true;
  }
  const Q3 ba = sub(b, a), dc = sub(d, c);
  const Q3 m = crs(ba, dc);
  if (m[0] == 0 && m[1] == 0 && m[2] == 0) return false;  // parallel: endpoints decide
  if (dt(crs(ba, sub(c, a)), sub(d, a)) != 0) return false;
  // Coplanar, not parallel: proper crossing in the projection along the dominant axis of m.
  const int ax = dominant_axis(m);
  return orient2(a, b, c, ax) * orient2(a, b, d, ax) <= 0 &&
         orient2(c, d, a, ax) * orient2(c, d, b, ax) <= 0;
}

inline bool vf_contact_at(const VertexFaceQuery& q, const mpq_class& t) {
  return point_in_triangle(at(q.p_t0, q.p_t1, t), at(q.a_t0, q.a_t1, t), at(q.b_t0, q.b_t1, t),
                           at(q.c_t0, q.c_t1, t));
}

inline bool ee_contact_at(const EdgeEdgeQuery& q, const mpq_class& t) {
  return segments_intersect(at(q.ea0_t0, q.ea0_t1, t), at(q.ea1_t0, q.ea1_t1, t),
                            at(q.eb0_t0, q.eb0_t1, t), at(q.eb1_t0, q.eb1_t1, t));
}

// ---- tiers against the rational oracle ------------------------------------------------

inline CcdResult oracle(const VertexFaceQuery& q) {
  return detail::vertex_face_ccd_rational(q);
}
inline CcdResult oracle(const EdgeEdgeQuery& q) {
  return detail::edge_edge_ccd_rational(q);
}
inline CcdResult exact_tier(const VertexFaceQuery& q) {
  return detail::vertex_face_ccd_exact(q);
}
inline CcdResult exact_tier(const EdgeEdgeQuery& q) {
  return detail::edge_edge_ccd_exact(q);
}
inline CcdResult exact_tier_gmp(const VertexFaceQuery& q) {
  return detail::vertex_face_ccd_exact_gmp(q);
}
inline CcdResult exact_tier_gmp(const EdgeEdgeQuery& q) {
  return detail::edge_edge_ccd_exact_gmp(q);
}
inline std::optional<CcdResult> double_tier(const VertexFaceQuery& q) {
  return detail::vertex_face_ccd_double(q);
}
inline std::optional<CcdResult> double_tier(const EdgeEdgeQuery& q) {
  return detail::edge_edge_ccd_double(q);
}
inline CcdResult public_ccd(const VertexFaceQuery& q) {
  return vertex_face_ccd(q);
}
inline CcdResult public_ccd(const EdgeEdgeQuery& q) {
  return edge_edge_ccd(q);
}

/// Same answer as the oracle: the same `hit`, and for a hit a time of impact that is a
/// valid bound too (the oracle's lies within 2^-21 below the earliest contact, every tier's
/// within 1e-6 below it, so they differ by less than that).
inline bool agrees(const CcdResult& x, const CcdResult& oracle) {
  if (x.hit != oracle.hit) return false;
  if (!x.hit) return x.toi == 1.0;
  return x.toi >= 0.0 && x.toi <= 1.0 && x.toi <= oracle.toi + 0x1p-21 &&
         x.toi >= oracle.toi - 1e-6;
}

/// The query's 8 points in the filter's order: triangle (or first edge) and then the
/// vertex (or second edge), at t0 and then at t1.
inline std::array<Vec3, 8> filter_points(const VertexFaceQuery& q) {
  return {q.a_t0, q.b_t0, q.c_t0, q.p_t0, q.a_t1, q.b_t1, q.c_t1, q.p_t1};
}
inline std::array<Vec3, 8> filter_points(const EdgeEdgeQuery& q) {
  return {q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1};
}

/// Exactly: do the four Bernstein coefficients of the coplanarity cubic share one strict
/// sign (so the four points are never coplanar and no contact is possible)?
inline bool never_coplanar_exact(const std::array<Vec3, 8>& x) {
  auto q3 = [](const Vec3& v) { return Q3{mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2])}; };
  const Q3 u0 = sub(q3(x[1]), q3(x[0])), v0 = sub(q3(x[2]), q3(x[0])), w0 = sub(q3(x[3]), q3(x[0]));
  const Q3 u1 = sub(q3(x[5]), q3(x[4])), v1 = sub(q3(x[6]), q3(x[4])), w1 = sub(q3(x[7]), q3(x[4]));
  auto det = [](const Q3& a, const Q3& b, const Q3& c) { return dt(a, crs(b, c)); };
  const mpq_class b[4] = {det(u0, v0, w0), det(u1, v0, w0) + det(u0, v1, w0) + det(u0, v0, w1),
                          det(u0, v1, w1) + det(u1, v0, w1) + det(u1, v1, w0), det(u1, v1, w1)};
  bool positive = true, negative = true;
  for (const auto& c : b) {
    positive &= c > 0;
    negative &= c < 0;
  }
  return positive || negative;
}

}  // namespace tailor::test

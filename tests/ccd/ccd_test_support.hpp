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
#include <string>
#include <vector>

#include "tailor/ccd/ccd.hpp"

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

}  // namespace tailor::test

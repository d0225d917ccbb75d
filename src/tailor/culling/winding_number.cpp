#include "tailor/culling/winding_number.hpp"

#include <algorithm>

#include "tailor/geometry/orientation_predicates.hpp"

namespace tailor {
namespace {

enum class Crossing { none, behind, in_front, degenerate, on_triangle };

// Whether every nonzero sign agrees, and how many are zero.
struct SignAgreement {
  bool agree = true;
  int zeros = 0;
};

SignAgreement agreement(int s1, int s2, int s3) {
  SignAgreement result;
  int seen = 0;
  for (int s : {s1, s2, s3}) {
    if (s == 0) {
      ++result.zeros;
    } else if (seen == 0) {
      seen = s;
    } else if (s != seen) {
      result.agree = false;
    }
  }
  return result;
}

// How the segment from `point` to `far` (outside the surface's box, so on no triangle)
// meets triangle `t`; `point_side` caches orient3d(t, point) (2: not computed yet).
Crossing crossing(const TriangleCorners& t, signed char& point_side, const Vec3& point,
                  const Vec3& far) {
  for (int axis = 0; axis < 3; ++axis) {  // exact box rejection
    const double lo = std::min({t[0][axis], t[1][axis], t[2][axis]});
    const double hi = std::max({t[0][axis], t[1][axis], t[2][axis]});
    if (std::max(point[axis], far[axis]) < lo || std::min(point[axis], far[axis]) > hi) {
      return Crossing::none;
    }
  }
  if (point_side == 2) point_side = static_cast<signed char>(orient3d(t[0], t[1], t[2], point));
  const int far_side = orient3d(t[0], t[1], t[2], far);
  if (point_side != 0 && (far_side == 0 || far_side == point_side)) return Crossing::none;
  if (point_side == 0 && far_side == 0) return Crossing::degenerate;  // segment in the plane
  // The segment meets the plane at one point; is it inside the triangle?
  const SignAgreement edges =
      agreement(orient3d(point, far, t[0], t[1]), orient3d(point, far, t[1], t[2]),
                orient3d(point, far, t[2], t[0]));
  if (!edges.agree) return Crossing::none;
  if (edges.zeros > 0) return Crossing::degenerate;  // through an edge or a vertex
  if (point_side == 0) return Crossing::on_triangle;
  return point_side < 0 ? Crossing::behind : Crossing::in_front;
}

}  // namespace

std::optional<int> winding_number(const std::vector<TriangleCorners>& triangles,
                                  const Vec3& point) {
  if (triangles.empty()) return std::nullopt;
  Vec3 lo = point, hi = point;
  for (const TriangleCorners& t : triangles) {
    for (const Vec3& p : t) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  const Vec3 span = hi - lo;
  const double reach = span.maxCoeff() + 1.0;
  // Far points: along the six axis directions first (the box test then rejects almost
  // every triangle), then oblique ones in case those pass through a vertex or an edge.
  std::vector<Vec3> far_points;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 plus = point, minus = point;
    plus[axis] = hi[axis] + reach;
    minus[axis] = lo[axis] - reach;
    far_points.push_back(plus);
    far_points.push_back(minus);
  }
  const double fractions[][2] = {{0.381966, 0.618034},
                                 {0.723607, 0.145898},
                                 {0.236068, 0.854102},
                                 {0.527864, 0.291796},
                                 {0.944272, 0.472136}};
  for (const auto& f : fractions) {
    far_points.push_back({hi.x() + reach, lo.y() + f[0] * span.y(), lo.z() + f[1] * span.z()});
  }

  std::vector<signed char> sides(triangles.size(), 2);
  for (const Vec3& far : far_points) {
    int winding = 0;
    bool degenerate = false;
    for (std::size_t i = 0; i < triangles.size() && !degenerate; ++i) {
      switch (crossing(triangles[i], sides[i], point, far)) {
        case Crossing::none:
          break;
        case Crossing::behind:
          ++winding;
          break;
        case Crossing::in_front:
          --winding;
          break;
        case Crossing::degenerate:
          degenerate = true;
          break;
        case Crossing::on_triangle:
          return std::nullopt;
      }
    }
    if (!degenerate) return winding;
  }
  return std::nullopt;
}

}  // namespace tailor

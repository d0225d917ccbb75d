#include "tailor/culling/contour_test.hpp"

#include "tailor/culling/certified_bernstein.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <vector>

namespace tailor {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A vector that moves linearly over the step: value at t=0 and t=1.
struct Moving {
  Vec3 v0, v1;
  double magnitude() const { return v0.norm() + v1.norm(); }
};

// A quadratic in t on the step, every coefficient known to within one certified bound.
using Quadratic = CertifiedBernstein<2>;

Quadratic quadratic(double c0, double c1, double c2, double bound) {
  return {{c0, c1, c2}, {bound, bound, bound}};
}

// a·(u(t)×v(t)): the 2D orientation in the projection along a.
Quadratic orientation(const Moving& u, const Moving& v, const Vec3& a) {
  return quadratic(a.dot(u.v0.cross(v.v0)), 0.5 * a.dot(u.v0.cross(v.v1) + u.v1.cross(v.v0)),
                   a.dot(u.v1.cross(v.v1)), 32 * kEps * u.magnitude() * v.magnitude() * a.norm());
}

// |a|² (u⊥·v⊥) = (u·v)|a|² - (u·a)(v·a): the projected dot product, scaled.
Quadratic projected_dot(const Moving& u, const Moving& v, const Vec3& a) {
  const double aa = a.squaredNorm();
  const double ua0 = u.v0.dot(a), ua1 = u.v1.dot(a), va0 = v.v0.dot(a), va1 = v.v1.dot(a);
  return quadratic(u.v0.dot(v.v0) * aa - ua0 * va0,
                   0.5 * ((u.v0.dot(v.v1) + u.v1.dot(v.v0)) * aa - ua0 * va1 - ua1 * va0),
                   u.v1.dot(v.v1) * aa - ua1 * va1, 32 * kEps * u.magnitude() * v.magnitude() * aa);
}

Moving difference(const Positions& x0, const Positions& x1, Index from, Index to) {
  return {x0.row(to) - x0.row(from), x1.row(to) - x1.row(from)};
}

// Depth of the dyadic subdivision of the step for the corner and crossing certificates.
constexpr int kMaxDepth = 3;

// Consecutive edges u = (w[i-1], w[i]) and v = (w[i], w[i+1]) meet only at w[i] while
// they turn strictly one way, or while their projected dot product stays positive.
bool corner_stays_simple(const Moving& u, const Moving& v, const Vec3& a) {
  const Quadratic dot = projected_dot(u, v, a);
  // Most corners of a boundary are nearly straight: the dot alone settles them.
  if (dot.sign_on(0, 1) > 0) return true;
  const Quadratic turn = orientation(u, v, a);
  return holds_piecewise(
      [&](double lo, double hi) { return dot.sign_on(lo, hi) > 0 || turn.sign_on(lo, hi) != 0; },
      kMaxDepth);
}

// Segments pq and rs certainly disjoint: on each piece of the step, r and s strictly on
// one side of the line pq, or p and q strictly on one side of the line rs. Collinear
// segments pass neither test (consecutive boundary edges along one straight line of the
// mesh: a tube's generators, a grid's rows, which a rigid motion keeps collinear), so
// then also: r and s strictly beyond q along pq, or strictly before p (the line through
// q, or p, perpendicular to pq has pq on one side and rs strictly on the other).
bool certainly_disjoint(const Positions& x0, const Positions& x1, Index p, Index q, Index r,
                        Index s, const Vec3& a) {
  const Moving pq = difference(x0, x1, p, q), rs = difference(x0, x1, r, s);
  const Quadratic side_r = orientation(pq, difference(x0, x1, p, r), a);
  const Quadratic side_s = orientation(pq, difference(x0, x1, p, s), a);
  const Quadratic side_p = orientation(rs, difference(x0, x1, r, p), a);
  const Quadratic side_q = orientation(rs, difference(x0, x1, r, q), a);
  const auto by_sides = [&](double lo, double hi) {
    const int r_sign = side_r.sign_on(lo, hi);
    if (r_sign != 0 && r_sign == side_s.sign_on(lo, hi)) return true;
    const int p_sign = side_p.sign_on(lo, hi);
    return p_sign != 0 && p_sign == side_q.sign_on(lo, hi);
  };
  if (holds_piecewise(by_sides, kMaxDepth)) return true;
  const Quadratic beyond_r = projected_dot(pq, difference(x0, x1, q, r), a);
  const Quadratic beyond_s = projected_dot(pq, difference(x0, x1, q, s), a);
  const Quadratic before_r = projected_dot(pq, difference(x0, x1, p, r), a);
  const Quadratic before_s = projected_dot(pq, difference(x0, x1, p, s), a);
  return holds_piecewise(
      [&](double lo, double hi) {
        if (by_sides(lo, hi)) return true;
        if (beyond_r.sign_on(lo, hi) > 0 && beyond_s.sign_on(lo, hi) > 0) return true;
        return before_r.sign_on(lo, hi) < 0 && before_s.sign_on(lo, hi) < 0;
      },
      kMaxDepth);
}

struct Box2 {
  double min_x, max_x, min_y, max_y;
  double min_sum, max_sum;  // of x + y
  double reach;             // squared distance of its farthest corner from the origin
  Index edge;
};

// Loops of fewer edges are tested by the calling task alone; a longer loop (the root of a
// mesh that the cone certifies whole: 3,000 edges at a million triangles) is the only work
// of its traversal, so its tests run in parallel.
constexpr Index kParallelEdges = 512;
constexpr Index kEdgesPerTask = 128;

// Whether `holds(i)` for every i in [0, n): in parallel for long loops, stopping soon after
// the first failure. The answer does not depend on the order.
template <class Holds>
bool holds_for_all(Index n, const Holds& holds) {
  if (n < kParallelEdges) {
    for (Index i = 0; i < n; ++i) {
      if (!holds(i)) return false;
    }
    return true;
  }
  std::atomic<bool> all{true};
  tbb::parallel_for(tbb::blocked_range<Index>(0, n, kEdgesPerTask),
                    [&](const tbb::blocked_range<Index>& range) {
                      for (Index i = range.begin(); i < range.end(); ++i) {
                        if (!all.load(std::memory_order_relaxed)) return;
                        if (!holds(i)) {
                          all.store(false, std::memory_order_relaxed);
                          return;
                        }
                      }
                    });
  return all.load();
}

}  // namespace

bool contour_stays_simple(std::span<const Index> loop, const Positions& x0, const Positions& x1,
                          const Vec3& axis) {
  const Index m = static_cast<Index>(loop.size());
  if (m < 3) return false;
  auto at = [&](Index i) { return loop[static_cast<std::size_t>((i % m + m) % m)]; };

  // Each edge's box in a plane normal to the axis, to prune the non-adjacent pairs below.
  // The boxes are only a filter, padded for the rounding of the approximate basis; the
  // certificates use the axis itself.
  const Vec3 e1 = axis.unitOrthogonal();
  const Vec3 e2 = axis.normalized().cross(e1);
  const Vec3 origin = x0.row(loop[0]);
  std::vector<Box2> boxes(static_cast<std::size_t>(m));

  // One pass over the edges builds the boxes and tests the corners: consecutive edges meet
  // only at their shared vertex, as they never fold back onto each other (projected dot
  // stays positive) or they turn strictly one way throughout.
  const bool corners_simple = holds_for_all(m, [&](Index i) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    Box2 box{kInfinity, -kInfinity, kInfinity, -kInfinity, 0, 0, 0, i};
    for (Index vertex : {at(i), at(i + 1)}) {
      for (const Positions* x : {&x0, &x1}) {
        const Vec3 d = Vec3(x->row(vertex)) - origin;
        const double px = d.dot(e1), py = d.dot(e2);
        box.min_x = std::min(box.min_x, px), box.max_x = std::max(box.max_x, px);
        box.min_y = std::min(box.min_y, py), box.max_y = std::max(box.max_y, py);
        box.reach = std::max(box.reach, d.squaredNorm());
      }
    }
    box.min_sum = box.min_x + box.min_y, box.max_sum = box.max_x + box.max_y;
    boxes[static_cast<std::size_t>(i)] = box;
    return corner_stays_simple(difference(x0, x1, at(i - 1), at(i)),
                               difference(x0, x1, at(i), at(i + 1)), axis);
  });
  if (!corners_simple) return false;
  if (m == 3) return true;  // a triangle has no non-adjacent edge pair

  // Sweep along x + y, not x: a mesh's straight boundaries usually run along a coordinate
  // axis, and all the boxes of such a side would overlap in x. Boxes that overlap within
  // `pad` in x and in y overlap within 2·pad in x + y (3·pad covers the sums' rounding).
  double reach = 0;
  for (const Box2& box : boxes) reach = std::max(reach, box.reach);
  const double pad = 1e-9 * std::sqrt(reach);
  // Ties may sort either way: both orders check the same pairs.
  tbb::parallel_sort(boxes.begin(), boxes.end(),
                     [](const Box2& a, const Box2& b) { return a.min_sum < b.min_sum; });
  return holds_for_all(m, [&](Index position) {
    const auto i = static_cast<std::size_t>(position);
    for (std::size_t j = i + 1; j < boxes.size() && boxes[j].min_sum <= boxes[i].max_sum + 3 * pad;
         ++j) {
      if (boxes[j].min_x > boxes[i].max_x + pad || boxes[i].min_x > boxes[j].max_x + pad) continue;
      if (boxes[j].min_y > boxes[i].max_y + pad || boxes[i].min_y > boxes[j].max_y + pad) continue;
      const Index a = boxes[i].edge, b = boxes[j].edge;
      const Index gap = std::abs(a - b);
      if (gap == 1 || gap == m - 1) continue;  // adjacent: checked above
      if (!certainly_disjoint(x0, x1, at(a), at(a + 1), at(b), at(b + 1), axis)) return false;
    }
    return true;
  });
}

}  // namespace tailor

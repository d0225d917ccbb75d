/// @file
/// The certified double path: interval subdivision of [0, 1] in increasing t. A
/// subinterval is skipped only when every contact branch is certainly impossible on all
/// of it; a hit is claimed only when f certainly changes sign across a subinterval on
/// which every inside condition is certainly strictly positive. Anything else goes to
/// the exact path. All bounds are rigorous (interval.hpp); there is no epsilon.

#include <array>
#include <cmath>
#include <optional>

#include "tailor/ccd/ccd_exact.hpp"
#include "tailor/ccd/ccd_systems.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"
#include "tailor/ccd/interval.hpp"

namespace tailor::detail {

namespace {

using IV = V3<Interval>;
using Bern = std::array<Interval, 4>;

/// Subintervals this narrow (2^-20 < 1e-6) locate the time of impact well enough.
constexpr double kToiWidth = 0x1p-20;
/// Work limits before giving the query to the exact path.
constexpr int kMaxDepth = 36;
constexpr int kMaxNodes = 128;

/// Coordinates beyond this (or non-finite) go to the exact path: keeps every interval
/// product finite, so no NaN can arise.
bool in_range(std::initializer_list<const Vec3*> points) {
  for (const Vec3* x : points) {
    for (int k = 0; k < 3; ++k) {
      if (!(std::fabs((*x)[k]) <= 0x1p200)) return false;
    }
  }
  return true;
}

Interval half(const Interval& x) {
  return {next_down(x.lo * 0.5), next_up(x.hi * 0.5)};
}

/// Rigorous Bernstein coefficients of f on [0, 1] from the certified filter values;
/// `identically_zero` is set when every term of every coefficient is exactly zero.
std::optional<Bern> coplanarity_bernstein(const Vec3& a0, const Vec3& b0, const Vec3& c0,
                                          const Vec3& d0, const Vec3& a1, const Vec3& b1,
                                          const Vec3& c1, const Vec3& d1, bool& identically_zero) {
  double value[4], bound[4];
  if (!coplanarity_bernstein_double(a0, b0, c0, d0, a1, b1, c1, d1, value, bound)) {
    return std::nullopt;
  }
  identically_zero = bound[0] == 0.0 && bound[1] == 0.0 && bound[2] == 0.0 && bound[3] == 0.0;
  Bern r;
  for (int i = 0; i < 4; ++i) {
    double lo = next_down(value[i] - bound[i]);
    double hi = next_up(value[i] + bound[i]);
    if (i == 1 || i == 2) {  // the filter values are 3β1, 3β2
      lo = next_down(lo / 3.0);
      hi = next_up(hi / 3.0);
    }
    r[i] = {lo, hi};
  }
  return r;
}

/// de Casteljau split at the middle, in interval arithmetic.
void split(const Bern& b, Bern& left, Bern& right) {
  const Interval b01 = half(b[0] + b[1]), b12 = half(b[1] + b[2]), b23 = half(b[2] + b[3]);
  const Interval b012 = half(b01 + b12), b123 = half(b12 + b23);
  const Interval mid = half(b012 + b123);
  left = {b[0], b01, b012, mid};
  right = {mid, b123, b23, b[3]};
}

/// f certainly has no root on the subinterval (all coefficients of one strict sign).
bool excludes_zero(const Bern& b) {
  return (b[0].positive() && b[1].positive() && b[2].positive() && b[3].positive()) ||
         (b[0].negative() && b[1].negative() && b[2].negative() && b[3].negative());
}

/// f certainly changes sign between the ends of the subinterval.
bool sign_change(const Bern& b) {
  return (b[0].positive() && b[3].negative()) || (b[0].negative() && b[3].positive());
}

/// Enclosure of the moving point over [t1, t2].
IV moving_point(const Vec3& x0, const Vec3& x1, double t1, double t2) {
  auto coord = [&](int k) {
    const Interval a(x0[k]), d = Interval(x1[k]) - a;
    return hull(a + Interval(t1) * d, a + Interval(t2) * d);
  };
  return {coord(0), coord(1), coord(2)};
}

bool point_segment_empty(const IV& p, const IV& a, const IV& b) {
  const PointSegment<Interval> s = point_segment(p, a, b);
  return s.cross.x.nonzero() || s.cross.y.nonzero() || s.cross.z.nonzero() || s.along.negative() ||
         s.within.negative();
}

struct Node {
  double t1, t2;
  int depth;
  Bern f;
};

/// Outcome of one subinterval.
enum class NodeState {
  empty,          ///< no contact anywhere on the closed subinterval
  root_hit,       ///< f changes sign and only roots of f can be contacts here
  contact_at_t1,  ///< a contact at the subinterval's start (f identically zero)
  contact,        ///< a contact somewhere in the subinterval (f identically zero)
  unknown,
};

/// Earliest root of f inside a node across which f certainly changes sign and where no
/// contact other than a root of f is possible: toi within kToiWidth, or nullopt.
std::optional<double> earliest_root(const Node& start) {
  Node stack[kMaxDepth + 2];
  int top = 0, nodes = 0;
  stack[top++] = start;
  while (top > 0) {
    const Node n = stack[--top];
    if (++nodes > kMaxNodes) return std::nullopt;
    if (excludes_zero(n.f)) continue;
    if (n.t2 - n.t1 <= kToiWidth) {
      // Everything before n.t1 is root-free; a certified root here bounds the earliest.
      if (sign_change(n.f)) return n.t1;
      return std::nullopt;
    }
    if (n.depth >= kMaxDepth) return std::nullopt;
    const double tm = 0.5 * (n.t1 + n.t2);
    Node l{n.t1, tm, n.depth + 1, {}}, r{tm, n.t2, n.depth + 1, {}};
    split(n.f, l.f, r.f);
    stack[top++] = r;
    stack[top++] = l;
  }
  return std::nullopt;
}

/// The subdivision driver; `classify` says whether a node (where f may vanish) is empty,
/// a certified hit, or unknown.
template <class Classify>
std::optional<CcdResult> subdivide(const Bern& f01, Classify&& classify) {
  Node stack[kMaxDepth + 2];
  int top = 0, nodes = 0;
  stack[top++] = Node{0.0, 1.0, 0, f01};
  while (top > 0) {
    const Node n = stack[--top];
    if (++nodes > kMaxNodes) return std::nullopt;
    // Every branch implies f = 0.
    if (excludes_zero(n.f)) continue;
    const NodeState s = classify(n.t1, n.t2, sign_change(n.f));
    // Everything before n.t1 is certified contact-free (left-first order).
    if (s == NodeState::empty) continue;
    if (s == NodeState::root_hit) {
      const std::optional<double> toi = earliest_root(n);
      if (!toi) return std::nullopt;
      return CcdResult{true, *toi, CcdPath::double_precision};
    }
    if (s == NodeState::contact_at_t1 || (s == NodeState::contact && n.t2 - n.t1 <= kToiWidth)) {
      return CcdResult{true, n.t1, CcdPath::double_precision};
    }
    if (n.depth >= kMaxDepth) return std::nullopt;
    const double tm = 0.5 * (n.t1 + n.t2);
    Node l{n.t1, tm, n.depth + 1, {}}, r{tm, n.t2, n.depth + 1, {}};
    split(n.f, l.f, r.f);
    stack[top++] = r;
    stack[top++] = l;
  }
  return CcdResult{false, 1.0, CcdPath::double_precision};
}

}  // namespace

std::optional<CcdResult> vertex_face_ccd_double(const VertexFaceQuery& q) {
  if (!in_range({&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1})) {
    return std::nullopt;
  }
  bool f_zero = false;
  const auto f =
      coplanarity_bernstein(q.a_t0, q.b_t0, q.c_t0, q.p_t0, q.a_t1, q.b_t1, q.c_t1, q.p_t1, f_zero);
  if (!f) return std::nullopt;
  auto points = [&](double t1, double t2) {
    return std::array<IV, 4>{
        moving_point(q.p_t0, q.p_t1, t1, t2), moving_point(q.a_t0, q.a_t1, t1, t2),
        moving_point(q.b_t0, q.b_t1, t1, t2), moving_point(q.c_t0, q.c_t1, t1, t2)};
  };
  // p certainly inside the open, non-degenerate triangle.
  auto strictly_inside = [](const FaceConditions<Interval>& fc) {
    return fc.N.positive() && fc.E_ab.positive() && fc.E_bc.positive() && fc.E_ca.positive();
  };
  return subdivide(*f, [&](double t1, double t2, bool f_changes_sign) {
    if (f_zero) {
      // Coplanar for the whole step: strictly inside at an instant is a contact then.
      const auto [p, a, b, c] = points(t1, t1);
      if (strictly_inside(face_conditions(p, a, b, c))) return NodeState::contact_at_t1;
    }
    const auto [p, a, b, c] = points(t1, t2);
    const FaceConditions<Interval> fc = face_conditions(p, a, b, c);
    // A root of f inside the open triangle: p is on no edge line (each E > 0), so the only
    // contacts on this node are roots of f.
    if (f_changes_sign && strictly_inside(fc)) return NodeState::root_hit;
    const bool face_empty =
        !(fc.N.hi > 0.0) || fc.E_ab.negative() || fc.E_bc.negative() || fc.E_ca.negative();
    if (face_empty && point_segment_empty(p, a, b) && point_segment_empty(p, b, c) &&
        point_segment_empty(p, c, a)) {
      return NodeState::empty;
    }
    if (f_zero && t2 - t1 <= kToiWidth) {
      const auto [p2, a2, b2, c2] = points(t2, t2);
      if (strictly_inside(face_conditions(p2, a2, b2, c2))) return NodeState::contact;
    }
    return NodeState::unknown;
  });
}

std::optional<CcdResult> edge_edge_ccd_double(const EdgeEdgeQuery& q) {
  if (!in_range({&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1,
                 &q.eb1_t1})) {
    return std::nullopt;
  }
  bool f_zero = false;
  const auto f = coplanarity_bernstein(q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1,
                                       q.eb0_t1, q.eb1_t1, f_zero);
  if (!f) return std::nullopt;
  auto points = [&](double t1, double t2) {
    return std::array<IV, 4>{
        moving_point(q.ea0_t0, q.ea0_t1, t1, t2), moving_point(q.ea1_t0, q.ea1_t1, t1, t2),
        moving_point(q.eb0_t0, q.eb0_t1, t1, t2), moving_point(q.eb1_t0, q.eb1_t1, t1, t2)};
  };
  // The lines certainly cross at interior points of both segments (0 < s, u < 1).
  auto strictly_crossing = [](const EdgeConditions<Interval>& ec) {
    return ec.M.positive() && ec.S_.positive() && ec.M_minus_S.positive() && ec.U.positive() &&
           ec.M_minus_U.positive();
  };
  return subdivide(*f, [&](double t1, double t2, bool f_changes_sign) {
    if (f_zero) {
      const auto [a, b, c, d] = points(t1, t1);
      if (strictly_crossing(edge_conditions(a, b, c, d))) return NodeState::contact_at_t1;
    }
    const auto [a, b, c, d] = points(t1, t2);
    const EdgeConditions<Interval> ec = edge_conditions(a, b, c, d);
    // Crossing at interior points: no endpoint lies on the other segment, so the only
    // contacts here are roots of f.
    if (f_changes_sign && strictly_crossing(ec)) return NodeState::root_hit;
    const bool main_empty = !(ec.M.hi > 0.0) || ec.S_.negative() || ec.M_minus_S.negative() ||
                            ec.U.negative() || ec.M_minus_U.negative();
    if (main_empty && point_segment_empty(a, c, d) && point_segment_empty(b, c, d) &&
        point_segment_empty(c, a, b) && point_segment_empty(d, a, b)) {
      return NodeState::empty;
    }
    if (f_zero && t2 - t1 <= kToiWidth) {
      const auto [a2, b2, c2, d2] = points(t2, t2);
      if (strictly_crossing(edge_conditions(a2, b2, c2, d2))) return NodeState::contact;
    }
    return NodeState::unknown;
  });
}

}  // namespace tailor::detail

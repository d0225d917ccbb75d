/// @file
/// The certified double tier. Every contact is a root of the coplanarity cubic f, so:
/// 1. isolate the roots of f in [0, 1] by Bernstein subdivision in double, with a
///    certified bound on every coefficient's error (a node whose coefficients certainly
///    share one sign holds no root; one certain sign change isolates one simple root);
/// 2. narrow each root, in increasing order, to a bracket [t_a, t_b] across which f
///    certainly changes sign (Newton, then two certified evaluations);
/// 3. decide the projected conditions of ccd_systems.hpp over the bracket in ball
///    arithmetic: certainly inside (a hit, toi = t_a) or certainly outside (next root).
/// Nodes where f's sign pattern stays uncertain can still be skipped when the projected
/// conditions certainly fail over the whole node. Anything else goes to the exact tier:
/// the tier never guesses, it only answers what its bounds prove.

#include "tailor/ccd/ccd_double.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "tailor/ccd/ball.hpp"
#include "tailor/ccd/ccd_exact.hpp"
#include "tailor/ccd/ccd_systems.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor::detail {

namespace {

using BV = V3<Ball>;

constexpr double kU = 0x1p-53;
/// Subdivision limits before giving the query to the exact tier.
constexpr int kMaxDepth = 16;
/// Brackets this narrow (2^-22 < 1e-6 / 2) locate the time of impact well enough.
constexpr double kToiWidth = 0x1p-22;

/// f's Bernstein coefficients on [0, 1] and a bound on their errors.
struct Cubic {
  bool zero = false;  // every term of every coefficient is exactly zero: f == 0
  double b[4];
  double error;      // |computed - exact| <= error for every coefficient at the root
  double magnitude;  // >= |every exact Bernstein coefficient on any subinterval|
};

/// Certified value of f at t (de Casteljau on the root coefficients): each level is a
/// convex combination, so the error grows by at most 4u * magnitude per level.
struct Value {
  double v, err;
  int sign() const { return v > err ? 1 : (v < -err ? -1 : 0); }
};

Value evaluate(const Cubic& f, double t, double* slope = nullptr) {
  const double s = 1.0 - t;
  double x0 = f.b[0], x1 = f.b[1], x2 = f.b[2], x3 = f.b[3];
  x0 = s * x0 + t * x1;
  x1 = s * x1 + t * x2;
  x2 = s * x2 + t * x3;
  x0 = s * x0 + t * x1;
  x1 = s * x1 + t * x2;
  if (slope != nullptr) *slope = 3.0 * (x1 - x0);
  const double v = s * x0 + t * x1;
  // 1 - t rounds (u), each level has two products and a sum: <= 5u magnitude per level.
  return {v, (f.error + 15.0 * kU * f.magnitude + kBallEta) * kBallInflate};
}

struct Node {
  double t1, t2;
  int depth;
  double c[4];
};

/// Position differences of a query relative to its first point, at t0 and the change
/// over the step, as balls (the differences are rounded once).
struct Motion {
  BV x0[3], dx[3];

  /// The three relative points at every t in the ball `t`.
  std::array<BV, 3> at(const Ball& t) const {
    std::array<BV, 3> r;
    for (int i = 0; i < 3; ++i) {
      r[i] = {x0[i].x + t * dx[i].x, x0[i].y + t * dx[i].y, x0[i].z + t * dx[i].z};
    }
    return r;
  }
};

Ball rounded_difference(double a, double b) {
  const double m = a - b;
  return {m, kU * std::fabs(m) * kBallInflate};
}

Motion make_motion(const Vec3* t0[4], const Vec3* t1[4]) {
  Motion m;
  for (int i = 0; i < 3; ++i) {
    const Vec3 &p0 = *t0[i + 1], &r0 = *t0[0], &p1 = *t1[i + 1], &r1 = *t1[0];
    const Ball x0[3] = {rounded_difference(p0[0], r0[0]), rounded_difference(p0[1], r0[1]),
                        rounded_difference(p0[2], r0[2])};
    const Ball x1[3] = {rounded_difference(p1[0], r1[0]), rounded_difference(p1[1], r1[1]),
                        rounded_difference(p1[2], r1[2])};
    m.x0[i] = {x0[0], x0[1], x0[2]};
    m.dx[i] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
  }
  return m;
}

/// The axis k with the largest |(x × y)_k| (midpoints only) and that component as a ball
/// (computing one ball component instead of three).
int largest_cross_axis(const BV& x, const BV& y, Ball& component_k) {
  const double c[3] = {x.y.m * y.z.m - x.z.m * y.y.m, x.z.m * y.x.m - x.x.m * y.z.m,
                       x.x.m * y.y.m - x.y.m * y.x.m};
  int k = 0;
  if (std::fabs(c[1]) > std::fabs(c[k])) k = 1;
  if (std::fabs(c[2]) > std::fabs(c[k])) k = 2;
  component_k = cross_component(x, y, k);
  return k;
}

enum class Verdict { outside, inside, unknown };

/// A root of f certified in [lo, hi] (sign_lo: f's sign at lo): what the exact assist
/// needs to settle the signs the balls leave open.
struct RootBracket {
  double lo, hi;
  int sign_lo;
  mutable bool used_exact = false;  // set when the exact assist decided a sign
};

/// VF projected test over every coplanar instant in the ball t: certainly no contact
/// (outside), certainly a contact (inside), or unknown. With a root bracket, signs the
/// balls cannot separate from zero are settled exactly (vertex_face_signs_at_root).
Verdict vf_verdict(const Motion& motion, const Ball& t, const VertexFaceQuery* query = nullptr,
                   const RootBracket* root = nullptr) {
  const auto [u, v, w] = motion.at(t);  // b - a, c - a, p - a
  Ball nk;
  const int k = largest_cross_axis(u, v, nk);
  const int s = nk.sign();
  if (s == 0) return Verdict::unknown;
  const BV zero{Ball(0.0), Ball(0.0), Ball(0.0)};
  int e[3] = {cross_component(u, w, k).sign(), cross_component(v - u, w - u, k).sign(),
              cross_component(zero - v, w - v, k).sign()};
  int open[3], count = 0;
  for (int i = 0; i < 3; ++i) {
    if (e[i] * s < 0) return Verdict::outside;
    if (e[i] == 0) open[count++] = i + 1;
  }
  if (count == 0) return Verdict::inside;
  if (root == nullptr) return Verdict::unknown;
  int exact[3];
  if (!vertex_face_signs_at_root(*query, k, {root->lo, root->hi, root->sign_lo},
                                 {open, static_cast<std::size_t>(count)}, exact)) {
    return Verdict::unknown;
  }
  root->used_exact = true;
  for (int i = 0; i < count; ++i) {
    if (exact[i] * s < 0) return Verdict::outside;
  }
  return Verdict::inside;  // every edge orientation agrees with n_k or vanishes
}

/// EE projected test: certainly apart, certainly meeting, or unknown (see vf_verdict).
Verdict ee_verdict(const Motion& motion, const Ball& t, const EdgeEdgeQuery* query = nullptr,
                   const RootBracket* root = nullptr) {
  const auto [u, v, w] = motion.at(t);  // b - a, c - a, d - a
  const BV dc = w - v;
  Ball mk;
  const int k = largest_cross_axis(u, dc, mk);
  if (mk.sign() == 0) return Verdict::unknown;
  const BV zero{Ball(0.0), Ball(0.0), Ball(0.0)};
  int o[4] = {cross_component(u, v, k).sign(), cross_component(u, w, k).sign(),
              cross_component(dc, zero - v, k).sign(), cross_component(dc, u - v, k).sign()};
  if (o[0] * o[1] > 0 || o[2] * o[3] > 0) return Verdict::outside;
  if (o[0] * o[1] < 0 && o[2] * o[3] < 0) return Verdict::inside;
  if (root == nullptr) return Verdict::unknown;
  int open[4], count = 0;
  for (int i = 0; i < 4; ++i) {
    if (o[i] == 0) open[count++] = i + 1;
  }
  int exact[4];
  if (!edge_edge_signs_at_root(*query, k, {root->lo, root->hi, root->sign_lo},
                               {open, static_cast<std::size_t>(count)}, exact)) {
    return Verdict::unknown;
  }
  root->used_exact = true;
  for (int i = 0; i < count; ++i) o[open[i] - 1] = exact[i];
  return o[0] * o[1] <= 0 && o[2] * o[3] <= 0 ? Verdict::inside : Verdict::outside;
}

/// A bracket [t_a, t_b] inside the isolating node where f certainly changes sign, at most
/// kToiWidth wide, or nullopt.
std::optional<std::array<double, 2>> bracket_root(const Cubic& f, const Node& node, int sign_left) {
  // Newton from the middle, kept inside the node, until its step is well below the
  // bracket we want (convergence is quadratic: the error is then far smaller still).
  double t = 0.5 * (node.t1 + node.t2), step = node.t2 - node.t1;
  for (int i = 0; i < 8 && std::fabs(step) > 0x1p-30; ++i) {
    double slope = 0.0;
    const Value v = evaluate(f, t, &slope);
    if (!(slope != 0.0)) break;
    const double next = t - v.v / slope;
    if (!(next > node.t1 && next < node.t2)) break;
    step = next - t;
    t = next;
  }
  double slope = 0.0;
  const Value at = evaluate(f, t, &slope);
  // Half-width where |f| should clear its error bound (and beyond Newton's last step),
  // then 16 and 256 times wider.
  double delta = std::fabs(slope) > 0.0 ? 4.0 * at.err / std::fabs(slope) : kToiWidth;
  delta = std::clamp(std::fmax(delta, 2.0 * std::fabs(step)), 0x1p-40, kToiWidth * 0.5);
  for (int attempt = 0; attempt < 3; ++attempt, delta = std::min(delta * 16.0, kToiWidth * 0.5)) {
    const double ta = std::max(node.t1, t - delta), tb = std::min(node.t2, t + delta);
    const int sa = ta == node.t1 ? sign_left : evaluate(f, ta).sign();
    const int sb = tb == node.t2 ? -sign_left : evaluate(f, tb).sign();
    if (sa == sign_left && sb == -sign_left && tb - ta <= kToiWidth) {
      return std::array<double, 2>{ta, tb};
    }
  }
  // Certified bisection of the node.
  double lo = node.t1, hi = node.t2;
  for (int i = 0; i < 64 && hi - lo > kToiWidth; ++i) {
    const double mid = 0.5 * (lo + hi);
    const int s = evaluate(f, mid).sign();
    if (s == 0) return std::nullopt;
    (s == sign_left ? lo : hi) = mid;
  }
  if (hi - lo > kToiWidth) return std::nullopt;
  return std::array<double, 2>{lo, hi};
}

int certain_sign(double c, double err) {
  return c > err ? 1 : (c < -err ? -1 : 0);
}

/// f == 0: every instant is coplanar. Left-first subdivision of [0, 1] by the projected
/// test: a node where no instant can be a contact is skipped; a contact certain at a node's
/// start (or at its end, once the node is narrower than kToiWidth) is the earliest, since
/// everything before was skipped.
template <class VerdictFn>
std::optional<CcdResult> decide_coplanar(VerdictFn&& verdict) {
  struct Span {
    double t1, t2;
    int depth;
  };
  constexpr int kMaxCoplanarDepth = 6, kMaxNodes = 12;
  Span stack[kMaxCoplanarDepth + 2];
  int top = 0, nodes = 0;
  stack[top++] = Span{0.0, 1.0, 0};
  while (top > 0) {
    const Span n = stack[--top];
    if (++nodes > kMaxNodes) return std::nullopt;
    if (verdict(ball_hull(n.t1, n.t2), nullptr) == Verdict::outside) continue;
    if (verdict(Ball(n.t1), nullptr) == Verdict::inside) {
      return CcdResult{true, n.t1, CcdPath::double_precision};
    }
    if (n.t2 - n.t1 <= kToiWidth) {
      if (verdict(Ball(n.t2), nullptr) == Verdict::inside) {
        return CcdResult{true, n.t1, CcdPath::double_precision};
      }
      return std::nullopt;
    }
    if (n.depth >= kMaxCoplanarDepth) return std::nullopt;
    const double tm = 0.5 * (n.t1 + n.t2);
    stack[top++] = Span{tm, n.t2, n.depth + 1};
    stack[top++] = Span{n.t1, tm, n.depth + 1};
  }
  return CcdResult{false, 1.0, CcdPath::double_precision};
}

/// The tier on one query: `verdict(t, root)` is vf_verdict or ee_verdict (root: the
/// certified bracket when t is one, else null).
template <class VerdictFn>
std::optional<CcdResult> decide(const Cubic& f, VerdictFn&& verdict) {
  if (f.zero) return decide_coplanar(verdict);
  Node stack[kMaxDepth + 2];
  int top = 0;
  stack[top++] = Node{0.0, 1.0, 0, {f.b[0], f.b[1], f.b[2], f.b[3]}};
  bool used_exact = false;
  while (top > 0) {
    const Node n = stack[--top];
    // Error of the node's coefficients: three averaging levels per split.
    const double err = (f.error + 3.0 * n.depth * (kU * f.magnitude + kBallEta)) * kBallInflate;
    int s[4];
    int changes = 0, last = 0;
    bool all_certain = true;
    for (int i = 0; i < 4; ++i) {
      s[i] = certain_sign(n.c[i], err);
      all_certain &= s[i] != 0;
      if (s[i] != 0 && last != 0 && s[i] != last) ++changes;
      if (s[i] != 0) last = s[i];
    }
    if (all_certain && changes == 0) continue;  // no root on the node
    if (all_certain && changes == 1) {
      // One simple root: decide the conditions across a narrow bracket around it.
      const auto bracket = bracket_root(f, n, s[0]);
      if (!bracket) return std::nullopt;
      const RootBracket root{(*bracket)[0], (*bracket)[1], s[0]};
      const Verdict v = verdict(ball_hull(root.lo, root.hi), &root);
      used_exact |= root.used_exact;
      const CcdPath path = used_exact ? CcdPath::exact_signs : CcdPath::double_precision;
      if (v == Verdict::inside) return CcdResult{true, root.lo, path};
      if (v == Verdict::outside) continue;
      return std::nullopt;
    }
    // Several roots, or a coefficient too close to zero to know: skip the node if no
    // coplanar instant in it can be a contact; if p may be inside throughout, only the
    // exact tier can tell whether f vanishes there.
    if (n.depth >= 2 || !all_certain) {
      const Verdict v = verdict(ball_hull(n.t1, n.t2), nullptr);
      if (v == Verdict::outside) continue;
      if (v == Verdict::inside && !all_certain) return std::nullopt;
    }
    if (n.depth >= kMaxDepth) return std::nullopt;
    const double tm = 0.5 * (n.t1 + n.t2);
    const double* c = n.c;
    const double c01 = 0.5 * (c[0] + c[1]), c12 = 0.5 * (c[1] + c[2]), c23 = 0.5 * (c[2] + c[3]);
    const double c012 = 0.5 * (c01 + c12), c123 = 0.5 * (c12 + c23);
    const double mid = 0.5 * (c012 + c123);
    stack[top++] = Node{tm, n.t2, n.depth + 1, {mid, c123, c23, c[3]}};
    stack[top++] = Node{n.t1, tm, n.depth + 1, {c[0], c01, c012, mid}};
  }
  return CcdResult{false, 1.0, used_exact ? CcdPath::exact_signs : CcdPath::double_precision};
}

/// f's coefficients from the filter's values (value[1], value[2] are 3 b1, 3 b2).
std::optional<Cubic> make_cubic(const CoplanarityBernstein& filter) {
  if (!filter.valid) return std::nullopt;
  Cubic f;
  f.b[0] = filter.value[0];
  f.b[1] = filter.value[1] / 3.0;
  f.b[2] = filter.value[2] / 3.0;
  f.b[3] = filter.value[3];
  double error = 0.0, magnitude = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double e =
        (i == 1 || i == 2) ? filter.bound[i] / 3.0 + kU * std::fabs(f.b[i]) : filter.bound[i];
    error = std::max(error, e);
    magnitude = std::max(magnitude, std::fabs(f.b[i]));
  }
  // Every term exactly zero: f is identically zero (coplanar for the whole step).
  f.zero = error == 0.0 && magnitude == 0.0;
  f.error = error * kBallInflate;
  f.magnitude = (magnitude + f.error) * kBallInflate;
  if (!std::isfinite(f.magnitude)) return std::nullopt;
  return f;
}

}  // namespace

CoplanarityBernstein coplanarity_bernstein(const VertexFaceQuery& q) {
  CoplanarityBernstein r;
  r.valid = coplanarity_bernstein_double({q.a_t0, q.b_t0, q.c_t0, q.p_t0},
                                         {q.a_t1, q.b_t1, q.c_t1, q.p_t1}, r.value, r.bound);
  return r;
}

CoplanarityBernstein coplanarity_bernstein(const EdgeEdgeQuery& q) {
  CoplanarityBernstein r;
  r.valid =
      coplanarity_bernstein_double({q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0},
                                   {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1}, r.value, r.bound);
  return r;
}

std::optional<CcdResult> vertex_face_ccd_double(const VertexFaceQuery& q,
                                                const CoplanarityBernstein& filter) {
  const auto f = make_cubic(filter);
  if (!f) return std::nullopt;
  const Vec3* t0[4] = {&q.a_t0, &q.b_t0, &q.c_t0, &q.p_t0};
  const Vec3* t1[4] = {&q.a_t1, &q.b_t1, &q.c_t1, &q.p_t1};
  const Motion motion = make_motion(t0, t1);
  return decide(
      *f, [&](const Ball& t, const RootBracket* root) { return vf_verdict(motion, t, &q, root); });
}

std::optional<CcdResult> edge_edge_ccd_double(const EdgeEdgeQuery& q,
                                              const CoplanarityBernstein& filter) {
  const auto f = make_cubic(filter);
  if (!f) return std::nullopt;
  const Vec3* t0[4] = {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0};
  const Vec3* t1[4] = {&q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
  const Motion motion = make_motion(t0, t1);
  return decide(
      *f, [&](const Ball& t, const RootBracket* root) { return ee_verdict(motion, t, &q, root); });
}

std::optional<CcdResult> vertex_face_ccd_double(const VertexFaceQuery& q) {
  return vertex_face_ccd_double(q, coplanarity_bernstein(q));
}

std::optional<CcdResult> edge_edge_ccd_double(const EdgeEdgeQuery& q) {
  return edge_edge_ccd_double(q, coplanarity_bernstein(q));
}

}  // namespace tailor::detail

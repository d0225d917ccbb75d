/// @file
/// Earliest-first branch and bound over time with ball arithmetic on boxes of positions,
/// and an exact rational decision on the narrowest intervals.

#include "tailor/ccd/thickness_ccd.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "tailor/ccd/advance_lanes.hpp"
#include "tailor/ccd/proximity_conditions.hpp"
#include "tailor/ccd/separating_axes.hpp"

namespace tailor {
namespace {

using detail::Ball;
using detail::Truth;
using detail::V3;

/// The four moving points of a query: at t = 0 and t = 1.
struct StepPoints {
  FourPoints x0, x1;
};

/// The vectors between the four points over a time interval t, as balls: each difference
/// is formed before the interval, (x0_i - x0_j) + t ((x1_i - x1_j) - (x0_i - x0_j)), so two
/// points moving together give a difference as narrow as the rounding, not two boxes apart.
/// The six differences i > j are formed once per interval (the conditions ask for them
/// about twenty times); d(j, i) is their negation, which is what forming it would give
/// (round-to-nearest is symmetric: the same midpoint negated, the same radius).
class BoxedStep {
 public:
  BoxedStep(const StepPoints& m, Ball t) {
    for (int i = 1; i < 4; ++i) {
      for (int j = 0; j < i; ++j) m_d[i][j] = difference(m, i, j, t);
    }
  }
  /// x_i - x_j over t, formed as above.
  static V3<Ball> difference(const StepPoints& m, int i, int j, Ball t) {
    const auto coordinate = [&](int k) {
      const Ball start = Ball(m.x0[i][k]) - Ball(m.x0[j][k]);
      const Ball end = Ball(m.x1[i][k]) - Ball(m.x1[j][k]);
      return start + t * (end - start);
    };
    return {coordinate(0), coordinate(1), coordinate(2)};
  }
  V3<Ball> d(int i, int j) const {
    if (i > j) return m_d[i][j];
    const V3<Ball>& v = m_d[j][i];
    return {-v.x, -v.y, -v.z};
  }

 private:
  std::array<std::array<V3<Ball>, 4>, 4> m_d;  // [i][j], i > j
};

/// The exact positions at the rational time t.
detail::PointSet<mpq_class> exact_at(const StepPoints& m, const mpq_class& t) {
  detail::PointSet<mpq_class> pts;
  for (int i = 0; i < 4; ++i) {
    const auto coordinate = [&](int k) {
      return mpq_class(mpq_class(m.x0[i][k]) + t * (mpq_class(m.x1[i][k]) - mpq_class(m.x0[i][k])));
    };
    pts.x[static_cast<std::size_t>(i)] = {coordinate(0), coordinate(1), coordinate(2)};
  }
  return pts;
}

/// Whether the cross product of (i1 - i0) and (j1 - j0) is zero for the whole step: it is a
/// quadratic in t, so zero at t = 0, 1/2 and 1 means zero everywhere (exact).
bool normal_always_zero(const StepPoints& m, std::array<int, 4> ends) {
  // Balls first: a component certainly nonzero at one time settles it (the usual case).
  for (const double t : {0.0, 0.5, 1.0}) {
    const V3<Ball> n = cross(BoxedStep::difference(m, ends[1], ends[0], Ball(t)),
                             BoxedStep::difference(m, ends[3], ends[2], Ball(t)));
    if (n.x.nonzero() || n.y.nonzero() || n.z.nonzero()) return false;
  }
  for (const mpq_class& t : {mpq_class(0), mpq_class(1, 2), mpq_class(1)}) {
    const detail::PointSet<mpq_class> pts = exact_at(m, t);
    const V3<mpq_class> n = cross(pts.d(ends[1], ends[0]), pts.d(ends[3], ends[2]));
    if (sgn(n.x) != 0 || sgn(n.y) != 0 || sgn(n.z) != 0) return false;
  }
  return true;
}

/// Whether points i and j coincide for the whole step.
bool always_together(const StepPoints& m, int i, int j) {
  return m.x0[i] == m.x0[j] && m.x1[i] == m.x1[j];
}

void check_query(const StepPoints& m, double h, const char* what) {
  if (!(h > 0) || !std::isfinite(h)) {
    throw std::invalid_argument(std::string(what) + ": the distance must be finite and > 0");
  }
  for (int i = 0; i < 4; ++i) {
    if (!m.x0[i].allFinite() || !m.x1[i].allFinite()) {
      throw std::invalid_argument(std::string(what) + ": non-finite coordinate");
    }
  }
}

/// Most advancement calls before the bisection takes over. A call costs a fraction of one
/// interval of the bisection, and pairs that come within h after t = 0 took ~19 intervals
/// after 12 calls (cloth-ball's thickness step: its search 6.7 → 3.3 s on one thread with
/// 200; 1,000 gained nothing more).
constexpr int kAdvanceSteps = 200;

/// The narrowest interval of the search: L w / 2 ≤ 1e-6 h (with room for rounding), and
/// w ≤ 1e-6, L = `speed`.
double narrowest_interval(double h, double speed) {
  return std::min(1e-6, 1.9e-6 * h / speed);
}

/// Where the advancement from t = 0 has got to when the search starts (the vector lanes'
/// PairAdvance): nothing yet by default.
struct AdvanceStart {
  double t = 0;
  int step = 0;
  double next = 0;        // the result of call `step`, when has_next
  bool has_next = false;  // call `step` has been made
};

/// The witness's reach against the widened h: h (1 + 0.9e-6) ≤ h √(1 + 2e-6).
double widened_witness_reach(double h) {
  return h * (1 + 0.9e-6);
}

/// Which distance a decision at one time is against: h, or h √(1 + 2e-6) ≤ (1 + 1e-6) h
/// (the narrowest intervals' midpoints).
enum class Reach { h, widened };

/// The search over [0, 1]; `conditions(points, h2, never)` is the pair's proximity
/// predicate over any number type, `speed` a bound on how fast its distance changes, and
/// `find_never()` the exact degeneracies the conditions drop (found on the first
/// evaluation: most pairs are decided by the advancement alone).
template <class Conditions, class FindNever>
class EarliestWithin {
 public:
  EarliestWithin(const StepPoints& m, const CornerDifferences& differences,
                 const ClosestWeights& at_start, PairShape shape, double h, double speed,
                 FindNever find_never, Conditions conditions, AdvanceStart start = {})
      : m_(m),
        at_start_(at_start),
        shape_(shape),
        h_(h),
        speed_(speed),
        advance_(m.x0, m.x1, differences, shape, h),
        find_never_(std::move(find_never)),
        conditions_(std::move(conditions)),
        h2_(Ball(h) * Ball(h)),
        // 500001 / 500000 rounds to the double 1.000002 within 2^-53 of it.
        widened_h2_(h2_ * Ball(1.000002, 0x1p-52)),
        narrowest_(narrowest_interval(h, speed)),
        start_(start) {}

  ThicknessResult run() {
    if (speed_ == 0) {  // nothing moves relative to the other primitive: one decision
      result_.intervals = 1;
      result_.hit = within_at(0.0, Reach::h);
      result_.toi = result_.hit ? 0.0 : 1.0;
      return result_;
    }
    double from = 0;
    if (whole_step_decided(from)) return result_;
    // Intervals still to look at, latest first, so the back is the earliest.
    std::array<std::pair<double, double>, 128> stack;
    int top = 0;
    stack[top++] = {from, 1.0};
    while (top > 0) {
      const auto [lo, hi] = stack[--top];
      ++result_.intervals;
      // The conditions over the interval's boxes on the narrowest intervals, before their
      // midpoint decides. Elsewhere the Lipschitz test at the midpoint below clears more for
      // less (cloth-ball: 17.2 -> 11.4 s, then 10.1 -> 9.2 s for the whole step); skipping
      // a proof can only split an interval further, never drop a pair.
      if (hi - lo <= narrowest_) {
        const Truth within = conditions_(BoxedStep{m_, detail::ball_hull(lo, hi)}, h2_, never());
        if (within == Truth::no) continue;
        if (within == Truth::yes) return hit(lo, false);
      }
      const double mid = 0.5 * lo + 0.5 * hi;
      if (clear_by_lipschitz(lo, hi, mid, hi - lo <= kExactLipschitzBelow)) continue;
      if (hi - lo <= narrowest_) {
        // Narrow enough: within h √(1 + 2e-6) ≤ (1 + 1e-6) h at the midpoint, or clear.
        if (within_at(mid, Reach::widened)) return hit(lo, false);
        continue;
      }
      if (result_.intervals >= kMaxThicknessIntervals || mid <= lo || mid >= hi ||
          top + 2 > static_cast<int>(stack.size())) {
        // Not splittable (the cap, the stack, or the doubles' resolution). Within h at its
        // end and at most 1e-6 wide: the first time is in the interval, and reported as
        // its start; otherwise reported there conservatively (exhausted).
        return hit(lo, hi - lo > 1e-6 || !exactly_within(hi, exact_h2(Reach::h)));
      }
      stack[top++] = {mid, hi};
      stack[top++] = {lo, mid};
    }
    return result_;
  }

 private:
  /// The whole step before any search. First the advancement from t = 0 (cheap; its first
  /// call proves t = 0 clear whenever it proves anything). When it proves nothing: the
  /// conditions over the whole step's boxes if the primitives move less than h relative to
  /// each other (the boxes are then tight; cloth-funnel), then within h at t = 0 (balls on
  /// the exact start positions, exact when they cannot tell), which makes the earliest
  /// time 0. Returns true with result_ set when that decides the pair; otherwise the
  /// search starts at `from`.
  bool whole_step_decided(double& from) {
    result_.intervals = 1;
    if (advance(from)) return true;
    if (from > 0) return false;
    Truth within = Truth::unknown;
    if (speed_ <= h_) {
      within = conditions_(BoxedStep{m_, detail::ball_hull(0, 1)}, h2_, never());
    }
    if (within == Truth::unknown) within = within_at(0.0, Reach::h) ? Truth::yes : Truth::unknown;
    if (within == Truth::yes) hit(0.0, false);
    return within != Truth::unknown;
  }

  // Undecided intervals try the Lipschitz exclusion in balls; those at most this wide also
  // in exact rationals when the balls cannot decide (slow, and rarely decisive wider).
  static constexpr double kExactLipschitzBelow = 1.0 / 16;

  /// Conservative advancement from t = 0 (ccd/separating_axes.hpp): each call clears
  /// [t, next] along the closest direction at t. Where it stalls (next - t below the
  /// narrowest width), the narrowest interval [next, next + w] is decided as in run() (within
  /// (1 + 1e-6) h at its midpoint: a hit at `next`, every earlier time being clear;
  /// otherwise clear as a whole, by the Lipschitz bound) and the advance resumes after it.
  /// Returns true with result_ set when that decides the pair; otherwise `from` is the end
  /// of the prefix [0, from] proven clear, where the bisection takes over.
  bool advance(double& from) {
    double t = start_.t;
    for (int step = start_.step; step < kAdvanceSteps; ++step) {
      const double next = step == start_.step && start_.has_next ? start_.next
                          : step == 0 ? advance_.clear_from_start(at_start_)
                                      : advance_.clear_from(t);
      if (next >= 1) return true;         // clear on the whole step: a miss
      if (next == t && step == 0) break;  // nothing proven (e.g. a degenerate triangle)
      if (next - t >= narrowest_) {
        t = next;
        continue;
      }
      const double end = std::min(1.0, next + narrowest_);
      ++result_.intervals;
      if (within_at(0.5 * next + 0.5 * end, Reach::widened)) {
        hit(next, false);
        return true;
      }
      if (end >= 1) return true;
      t = end;
    }
    from = t;
    return false;
  }

  ThicknessResult hit(double toi, bool exhausted) {
    result_.hit = true, result_.toi = toi, result_.exhausted = exhausted;
    return result_;
  }

  /// Whether the exact positions at the time t are within h (or the widened h): a witness
  /// of two points within h (1 + 0.9e-6) ≤ h √(1 + 2e-6) first (closest points in double,
  /// ccd/separating_axes.hpp; it can only say yes), then balls around the exact positions
  /// (they enclose them, so a decided answer is the exact one), exact rationals when the
  /// balls cannot decide.
  bool within_at(double t, Reach reach) const {
    const double witness_h = reach == Reach::h ? h_ : widened_witness_reach(h_);
    if (within_by_closest_points(m_.x0, m_.x1, t, shape_, witness_h)) return true;
    const Truth near =
        conditions_(BoxedStep{m_, Ball(t)}, reach == Reach::h ? h2_ : widened_h2_, never());
    if (near != Truth::unknown) return near == Truth::yes;
    return exactly_within(t, exact_h2(reach));
  }

  /// h² or h² · 500001 / 500000, exact.
  const mpq_class& exact_h2(Reach reach) const {
    std::optional<mpq_class>& value = reach == Reach::h ? exact_h2_ : exact_widened_h2_;
    if (!value) {
      value = mpq_class(h_) * mpq_class(h_);
      if (reach == Reach::widened) *value *= mpq_class(500001, 500000);
    }
    return *value;
  }

  /// Whether the exact positions at the time t are within sqrt(h2) (exact).
  bool exactly_within(double t, const mpq_class& h2) const {
    return conditions_(exact_at(m_, mpq_class(t)), h2, never()) == Truth::yes;
  }

  /// Farther than h + L w / 2 at the midpoint: no time of the interval comes within h.
  /// Balls around the midpoint's positions first, exact positions when they cannot decide.
  bool clear_by_lipschitz(double lo, double hi, double mid, bool exact) const {
    const double reach = (h_ + speed_ * (0.5 * (hi - lo))) * (1 + 1e-15);  // rounded up
    const Truth at_mid =
        conditions_(BoxedStep{m_, Ball(mid)}, Ball(Ball(reach) * Ball(reach)), never());
    if (at_mid != Truth::unknown || !exact) return at_mid == Truth::no;
    return !exactly_within(mid, mpq_class(reach) * mpq_class(reach));
  }

  const detail::NeverPresent& never() const {
    if (!never_) never_ = find_never_();
    return *never_;
  }

  const StepPoints& m_;
  ClosestWeights at_start_;  // the closest points' weights at t = 0, formed for the witness
  PairShape shape_;
  double h_, speed_;
  ClosestDirectionAdvance advance_;
  FindNever find_never_;
  mutable std::optional<detail::NeverPresent> never_;
  Conditions conditions_;
  Ball h2_, widened_h2_;
  // Formed on first use: most queries are decided by balls alone, and two rationals cost
  // more than a ball evaluation of the conditions.
  mutable std::optional<mpq_class> exact_h2_, exact_widened_h2_;
  double narrowest_;
  AdvanceStart start_;
  ThicknessResult result_;
};

/// What the tests before the search leave of a query: the decision they reached, or the
/// pair's corner differences and the weights of its closest points at t = 0.
struct Screened {
  std::optional<ThicknessResult> decided;
  std::optional<CornerDifferences> differences;
  ClosestWeights at_start;
};

/// The result for a pair already within h at t = 0.
ThicknessResult within_at_start() {
  ThicknessResult result;
  result.hit = true, result.toi = 0, result.intervals = 1;
  return result;
}

/// The coordinate axes, the pair's normals (unless the caller ran them), and the witness
/// at t = 0. The corner differences are formed after the witness when the normals are
/// skipped: the pairs within h at t = 0 (cloth-ball's thickness step: 419,425) never need
/// them.
Screened screen(const StepPoints& m, PairShape shape, double h, NormalTest normal_test) {
  Screened out;
  if (apart_along_a_coordinate_axis(m.x0, m.x1, shape, h)) {
    out.decided = ThicknessResult{};
    return out;
  }
  if (normal_test == NormalTest::run) {
    out.differences.emplace(m.x0, m.x1, shape);
    if (apart_along_normals(m.x0, m.x1, *out.differences, shape, h)) {
      out.decided = ThicknessResult{};
      return out;
    }
  }
  out.at_start = closest_weights(m.x0, shape);
  if (within_by_closest_points(m.x0, shape, h, out.at_start)) {
    out.decided = within_at_start();
    return out;
  }
  if (!out.differences) out.differences.emplace(m.x0, m.x1, shape);
  return out;
}

template <class Conditions, class FindNever>
ThicknessResult earliest_within(const StepPoints& m, const Screened& screened, PairShape shape,
                                double h, double speed, FindNever&& find_never,
                                Conditions&& conditions, AdvanceStart start = {}) {
  return EarliestWithin<std::decay_t<Conditions>, std::decay_t<FindNever>>(
             m, *screened.differences, screened.at_start, shape, h, speed,
             std::forward<FindNever>(find_never), std::forward<Conditions>(conditions), start)
      .run();
}

/// An upper bound of the largest relative displacement |Δi - Δj| over the pairs (i, j):
/// the point of one primitive and the point of the other are convex combinations of their
/// corners, so their relative displacement is a convex combination of these (norms rounded
/// up).
double fastest_relative(const StepPoints& m, std::initializer_list<std::pair<int, int>> pairs) {
  double v = 0;
  for (const auto& [i, j] : pairs) {
    v = std::max(v, ((m.x1[i] - m.x0[i]) - (m.x1[j] - m.x0[j])).norm());
  }
  return v * (1 + 1e-12);
}

/// A query's points (PairShape's order), checked.
StepPoints points_of(const VertexFaceQuery& q, double h) {
  const StepPoints m{{q.p_t0, q.a_t0, q.b_t0, q.c_t0}, {q.p_t1, q.a_t1, q.b_t1, q.c_t1}};
  check_query(m, h, "vertex_face_ccd_within");
  return m;
}
StepPoints points_of(const EdgeEdgeQuery& q, double h) {
  const StepPoints m{{q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0},
                     {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1}};
  check_query(m, h, "edge_edge_ccd_within");
  return m;
}

template <class Query>
constexpr PairShape kShapeOf =
    std::is_same_v<Query, VertexFaceQuery> ? PairShape::vertex_face : PairShape::edge_edge;

/// The bound on how fast the pair's distance changes (fastest_relative()).
double speed_of(const StepPoints& m, PairShape shape) {
  if (shape == PairShape::vertex_face) return fastest_relative(m, {{0, 1}, {0, 2}, {0, 3}});
  return fastest_relative(m, {{0, 2}, {0, 3}, {1, 2}, {1, 3}});
}

/// The search of a screened pair, its advancement started at `start`.
template <PairShape kShape>
ThicknessResult search(const StepPoints& m, const Screened& screened, double h, double speed,
                       AdvanceStart start = {}) {
  constexpr bool kVertexFace = kShape == PairShape::vertex_face;
  const auto find_never = [&m] {
    detail::NeverPresent never;
    if constexpr (kVertexFace) {
      never.normal = normal_always_zero(m, {1, 2, 1, 3});
      never.segment = {always_together(m, 1, 2), always_together(m, 2, 3), always_together(m, 3, 1),
                       false};
    } else {
      never.normal = normal_always_zero(m, {0, 1, 2, 3});
      const bool cd = always_together(m, 2, 3), ab = always_together(m, 0, 1);
      never.segment = {cd, cd, ab, ab};
    }
    return never;
  };
  const auto conditions = [](const auto& pts, const auto& h2, const detail::NeverPresent& n) {
    if constexpr (kVertexFace) {
      return detail::vertex_face(pts, h2, n);
    } else {
      return detail::edge_edge(pts, h2, n);
    }
  };
  return earliest_within(m, screened, kShape, h, speed, find_never, conditions, start);
}

template <class Query>
ThicknessResult one_query(const Query& q, double h, NormalTest normal_test) {
  constexpr PairShape kShape = kShapeOf<Query>;
  const StepPoints m = points_of(q, h);
  const Screened screened = screen(m, kShape, h, normal_test);
  if (screened.decided) return *screened.decided;
  return search<kShape>(m, screened, h, speed_of(m, kShape));
}

/// The screening and the pairs that do not move relative to each other one by one; the
/// others' advancements in vector lanes, then each one's search where it stopped.
template <class Query>
void batch(std::span<const Query> queries, double h, NormalTest normal_test,
           std::span<ThicknessResult> results) {
  constexpr PairShape kShape = kShapeOf<Query>;
  if (results.size() != queries.size()) {
    throw std::invalid_argument("ccd_within: as many results as queries");
  }
  struct Searched {
    std::size_t query;
    StepPoints m;
    Screened screened;
    double speed;
  };
  // Per thread, kept from call to call: a fresh vector for each chunk (~0.5 KB a query)
  // would be mapped and faulted in anew each time.
  thread_local std::vector<Searched> searched;
  thread_local std::vector<PairAdvance> advances;
  searched.clear();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const StepPoints m = points_of(queries[i], h);
    Screened screened = screen(m, kShape, h, normal_test);
    if (screened.decided) {
      results[i] = *screened.decided;
      continue;
    }
    const double speed = speed_of(m, kShape);
    if (speed == 0) {  // one decision, no advancement (EarliestWithin::run)
      results[i] = search<kShape>(m, screened, h, speed);
    } else {
      searched.push_back({i, m, std::move(screened), speed});
    }
  }
  advances.resize(searched.size());
  for (std::size_t j = 0; j < searched.size(); ++j) {
    const Searched& s = searched[j];
    advances[j] = {&s.m.x0, &s.m.x1, &*s.screened.differences, narrowest_interval(h, s.speed)};
  }
  advance_pairs(advances, kShape, h, widened_witness_reach(h), kAdvanceSteps);
  for (std::size_t j = 0; j < searched.size(); ++j) {
    const Searched& s = searched[j];
    const PairAdvance& a = advances[j];
    if (a.within_after) {  // EarliestWithin::advance's first narrow decision: a hit
      results[s.query] = {.hit = true, .toi = a.next, .intervals = 2, .exhausted = false};
      continue;
    }
    results[s.query] =
        search<kShape>(s.m, s.screened, h, s.speed, {a.t, a.step, a.next, a.has_next});
  }
}

}  // namespace

ThicknessResult vertex_face_ccd_within(const VertexFaceQuery& q, double h, NormalTest normal_test) {
  return one_query(q, h, normal_test);
}

ThicknessResult edge_edge_ccd_within(const EdgeEdgeQuery& q, double h, NormalTest normal_test) {
  return one_query(q, h, normal_test);
}

void vertex_face_ccd_within(std::span<const VertexFaceQuery> queries, double h,
                            NormalTest normal_test, std::span<ThicknessResult> results) {
  batch(queries, h, normal_test, results);
}

void edge_edge_ccd_within(std::span<const EdgeEdgeQuery> queries, double h, NormalTest normal_test,
                          std::span<ThicknessResult> results) {
  batch(queries, h, normal_test, results);
}

}  // namespace tailor

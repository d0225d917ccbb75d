/// @file
/// The minimum-separation CCD (vertex_face_ccd_within / edge_edge_ccd_within) per query on
/// the shared sets, on one core, with its accuracy against a long-double closest-point
/// oracle (tests/support/closest_points.hpp).
///
/// BM_ThicknessCcd/set/k: set 0 cloth-funnel 227, 1 the erleben scenes, 2 the unit tests of
/// ccd-queries; h = scale · 10^-k, the scale being the funnel frame's bounding-box diagonal
/// (3.99883) for the funnel and 1 for the hand-made sets (unit-sized scenes).
///
/// The oracle evaluates each pair's distance at 4,001 times over the step and at 201 times
/// in [toi, toi + 2e-6] (where a hit's first time within h lies: toi is a lower bound within
/// 1e-6), and refines the least of each grid by golden section. Counters:
/// - `within_h`: pairs the CCD reports within h;
/// - of those, `confirmed` (the oracle found a time at distance <= h), `tolerated` (its
///   least distance is in (h, (1 + 1e-6) h], the false positives the contract allows) and
///   `unconfirmed` (no time within (1 + 1e-6) h found: a false positive beyond the
///   contract, or an oracle miss; 0 expected);
/// - `oracle_fn`: pairs reported clear of which the oracle found a time at distance below
///   h (1 - 1e-9) (false negatives; 0 expected);
/// - `toi_late`: hits whose toi is after a time the oracle found below h (1 - 1e-9);
/// - `exhausted`: hits reported conservatively at the interval cap.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "query_sets.hpp"
#include "support/closest_points.hpp"
#include "tailor/ccd/thickness_ccd.hpp"

namespace tailor {
namespace {

using testing::L3;

L3 at(const Vec3& x0, const Vec3& x1, long double t) {
  return testing::wide(x0) + t * (testing::wide(x1) - testing::wide(x0));
}

long double distance_at(const VertexFaceQuery& q, long double t) {
  return testing::point_triangle_distance(at(q.p_t0, q.p_t1, t), at(q.a_t0, q.a_t1, t),
                                          at(q.b_t0, q.b_t1, t), at(q.c_t0, q.c_t1, t));
}

long double distance_at(const EdgeEdgeQuery& q, long double t) {
  return testing::segment_distance(at(q.ea0_t0, q.ea0_t1, t), at(q.ea1_t0, q.ea1_t1, t),
                                   at(q.eb0_t0, q.eb0_t1, t), at(q.eb1_t0, q.eb1_t1, t));
}

/// What the oracle found for one pair: the least distance and the earliest time it saw
/// below h (1 - 1e-9) (> 1: none).
struct OracleFinding {
  long double least = INFINITY;
  double first_below = 2;
};

/// Evaluates the pair on `samples` + 1 times spread over [begin, end] and refines the least
/// by golden section between its grid neighbours.
template <class Query>
void search(const Query& q, long double h, double begin, double end, int samples,
            OracleFinding& found) {
  const auto visit = [&](double t) {
    const long double d = distance_at(q, t);
    found.least = std::min(found.least, d);
    if (d < h * (1 - 1e-9L) && t < found.first_below) found.first_below = t;
    return d;
  };
  int best = 0;
  long double best_distance = INFINITY;
  for (int i = 0; i <= samples; ++i) {
    const long double d = visit(begin + (end - begin) * i / samples);
    if (d < best_distance) best_distance = d, best = i;
  }
  double low = begin + (end - begin) * std::max(best - 1, 0) / samples;
  double high = begin + (end - begin) * std::min(best + 1, samples) / samples;
  const double golden = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 80 && high > low; ++i) {
    const double m1 = high - golden * (high - low), m2 = low + golden * (high - low);
    if (visit(m1) < visit(m2)) {
      high = m2;
    } else {
      low = m1;
    }
  }
}

/// The accuracy counters of one set at one h (see the file comment).
struct Accuracy {
  std::size_t within_h = 0, confirmed = 0, tolerated = 0, unconfirmed = 0, oracle_fn = 0,
              toi_late = 0, exhausted = 0;

  template <class Query>
  void add(const Query& q, const ThicknessResult& r, long double h) {
    OracleFinding found;
    search(q, h, 0.0, 1.0, 4000, found);
    if (r.hit) search(q, h, r.toi, std::min(1.0, r.toi + 2e-6), 200, found);
    if (!r.hit) {
      oracle_fn += found.first_below <= 1;
      return;
    }
    ++within_h;
    exhausted += r.exhausted;
    toi_late += found.first_below < r.toi;
    if (found.least <= h) {
      ++confirmed;
    } else if (found.least <= h * (1 + 1e-6L)) {
      ++tolerated;
    } else {
      ++unconfirmed;
    }
  }
};

const QuerySet& query_set(int i) {
  static const QuerySet sets[3] = {funnel(), erleben(), unit_tests()};
  return sets[i];
}

const char* set_name(int i) {
  static const char* names[3] = {"funnel", "erleben", "unit-tests"};
  return names[i];
}

double thickness(int set, int k) {
  const double scale = set == 0 ? 3.99883 : 1.0;  // the funnel frame's diagonal
  return scale * std::pow(10.0, -k);
}

/// The CCD's verdicts and the oracle's counters for one set and h (computed once).
const Accuracy& accuracy(int set, int k) {
  static std::map<std::pair<int, int>, Accuracy> cache;
  auto [it, inserted] = cache.try_emplace({set, k});
  if (!inserted) return it->second;
  const QuerySet& s = query_set(set);
  const double h = thickness(set, k);
  for (const VertexFaceQuery& q : s.vf) it->second.add(q, vertex_face_ccd_within(q, h), h);
  for (const EdgeEdgeQuery& q : s.ee) it->second.add(q, edge_edge_ccd_within(q, h), h);
  return it->second;
}

void BM_ThicknessCcd(benchmark::State& state) {
  const int set = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const QuerySet& s = query_set(set);
  const double h = thickness(set, k);
  state.SetLabel(std::string(set_name(set)) + " h=" + std::to_string(h));
  std::size_t n = 0;
  for (auto _ : state) {
    for (const VertexFaceQuery& q : s.vf) benchmark::DoNotOptimize(vertex_face_ccd_within(q, h));
    for (const EdgeEdgeQuery& q : s.ee) benchmark::DoNotOptimize(edge_edge_ccd_within(q, h));
    n += s.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
  const Accuracy& a = accuracy(set, k);
  state.counters["queries"] = static_cast<double>(s.size());
  state.counters["h"] = h;
  const std::pair<const char*, std::size_t> counts[] = {
      {"within_h", a.within_h},       {"confirmed", a.confirmed}, {"tolerated", a.tolerated},
      {"unconfirmed", a.unconfirmed}, {"oracle_fn", a.oracle_fn}, {"toi_late", a.toi_late},
      {"exhausted", a.exhausted}};
  for (const auto& [name, count] : counts) state.counters[name] = static_cast<double>(count);
  state.counters["ns_per_query"] = benchmark::Counter(
      static_cast<double>(n), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_ThicknessCcd)
    ->ArgsProduct({{0, 1, 2}, {3, 6}})
    ->ArgNames({"set", "k"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tailor

BENCHMARK_MAIN();

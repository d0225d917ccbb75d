/// @file
/// Throughput of the exact CCD on one core, per data set and per tier, with the naive
/// floating-point cubic baseline on the same queries (and its false negatives / positives).
///
/// Data sets (first argument): 0 cloth-funnel (truth: mma_bool), 1 the erleben scenes and
/// 2 the unit tests of ccd-queries (truth column), 3 the folded-cloth contact step of the
/// project's generator at 100K triangles (the pairs the detector sends to the CCD; truth:
/// the exact CCD itself, which the tests check against the oracle), 4 the generated
/// degenerate set (100K queries, every category, scales 2^-20..2^20; truth: the rational
/// oracle), 5 extreme exponent spreads (issue 17: coordinates from 1e-309 to 1e148; truth:
/// the rational oracle).
///
/// BM_Ccd: the public pipeline; counters give the share of queries each tier decided.
/// BM_CcdTier/set/tier: the public pipeline on the queries that `tier` decided (0 filter,
/// 1 double, 2 exact_signs, 3 exact, 4 gmp): the cost per query of each tier's queries.
/// BM_ExactTier: the exact tier alone on every query of the set.
/// BM_Naive: the naive cubic solver (bench/naive_ccd.hpp), with its errors.

#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <string>
#include <vector>

#include "naive_ccd.hpp"
#include "query_sets.hpp"
#include "support/degenerate_ccd_queries.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/ccd/ccd_double.hpp"
#include "tailor/ccd/ccd_exact.hpp"
#include "tailor/ccd/ccd_rational.hpp"
#include "tailor/ccd/query_io.hpp"
#include "tailor/detection/ccd_query_export.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

/// The VF and EE pairs the detector sends to the CCD in the folded-cloth step (the same
/// pairs as `tailor detect --dump-queries`).
QuerySet folded_cloth() {
  const ProceduralStep step = make_folded_cloth_on_sphere(100000, 1);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  DetectionConfig config = DetectionConfig::preset("paper");
  config.keep_candidate_pairs = true;
  SelfCollisionDetector detector(mesh, step.x0, config);
  const DetectionResult result = detector.detect(step.x0, step.x1);
  StepCcdQueries queries =
      step_ccd_queries(mesh, step.x0, step.x1, config, result.candidate_triangle_pairs);
  QuerySet r;
  r.vf = std::move(queries.vertex_face);
  r.ee = std::move(queries.edge_edge);
  // Truth: the exact CCD (tests compare it with the rational oracle).
  for (const auto& q : r.vf) r.vf_truth.push_back(vertex_face_ccd(q).hit);
  for (const auto& q : r.ee) r.ee_truth.push_back(edge_edge_ccd(q).hit);
  return r;
}

/// Truth of generated queries from the rational oracle (parallel: it is slow).
void oracle_truth(QuerySet& r) {
  r.vf_truth.assign(r.vf.size(), false);
  r.ee_truth.assign(r.ee.size(), false);
  std::vector<char> vf(r.vf.size()), ee(r.ee.size());
  tbb::parallel_for(std::size_t{0}, r.vf.size(),
                    [&](std::size_t i) { vf[i] = detail::vertex_face_ccd_rational(r.vf[i]).hit; });
  tbb::parallel_for(std::size_t{0}, r.ee.size(),
                    [&](std::size_t i) { ee[i] = detail::edge_edge_ccd_rational(r.ee[i]).hit; });
  for (std::size_t i = 0; i < vf.size(); ++i) r.vf_truth[i] = vf[i];
  for (std::size_t i = 0; i < ee.size(); ++i) r.ee_truth[i] = ee[i];
}

QuerySet degenerate() {
  QuerySet r;
  testing::DegenerateQueryGenerator gen(2026);
  for (int i = 0; i < 100000; ++i) {
    const testing::DegenerateQuery q = gen.next();
    if (q.vertex_face) {
      r.vf.push_back(q.vf);
    } else {
      r.ee.push_back(q.ee);
    }
  }
  oracle_truth(r);
  return r;
}

/// Issue 17: one coordinate a subnormal, others up to 1e148, in the degenerate
/// configurations of CcdDegenerate.ExtremeExponentSpread, crossed with small shifts.
QuerySet extreme_spread() {
  QuerySet r;
  const double huge = 1e148, tiny = 1e-309;
  for (int i = 0; i < 64; ++i) {
    const double a_x = (i & 1) ? tiny : 0.0, c_x = (i & 2) ? -tiny : tiny;
    const double y = 1.0 + (i >> 2);
    r.ee.push_back({{a_x, 0, 0},
                    {huge, 0, 0},
                    {c_x, y, 1},
                    {c_x, y, 2},
                    {a_x, 0, 0},
                    {huge, 0, 0},
                    {c_x, -y, -1},
                    {c_x, -y, 0}});
    r.vf.push_back({{c_x, tiny, y},
                    {a_x, 0, 0},
                    {huge, 0, 0},
                    {0, huge, 0},
                    {c_x, tiny, -y},
                    {a_x, 0, 0},
                    {huge, 0, 0},
                    {0, huge, 0}});
  }
  oracle_truth(r);
  return r;
}

const QuerySet& set(int i) {
  static QuerySet sets[6];
  static bool loaded[6] = {};
  if (!loaded[i]) {
    switch (i) {
      case 0:
        sets[i] = funnel();
        break;
      case 1:
        sets[i] = erleben();
        break;
      case 2:
        sets[i] = unit_tests();
        break;
      case 3:
        sets[i] = folded_cloth();
        break;
      case 4:
        sets[i] = degenerate();
        break;
      default:
        sets[i] = extreme_spread();
    }
    loaded[i] = true;
  }
  return sets[i];
}

const char* set_name(int i) {
  static const char* names[6] = {"funnel",       "erleben",    "unit-tests",
                                 "folded-cloth", "degenerate", "extreme-spread"};
  return names[i];
}

/// Runs `fn` over the set's queries (VF then EE, or the subset `vf_only` / `ee_only`)
/// and reports per-path shares and errors against the truth.
template <class VfFn, class EeFn>
void run_set(benchmark::State& state, const QuerySet& s, const std::vector<std::size_t>& vf_idx,
             const std::vector<std::size_t>& ee_idx, VfFn&& vf_fn, EeFn&& ee_fn) {
  std::size_t paths[kCcdPathCount] = {};
  std::size_t fn = 0, fp = 0, n = 0;
  for (auto _ : state) {
    std::fill(std::begin(paths), std::end(paths), 0);
    fn = fp = 0;
    for (std::size_t i : vf_idx) {
      const CcdResult r = vf_fn(s.vf[i]);
      benchmark::DoNotOptimize(r);
      ++paths[static_cast<int>(r.path)];
      fn += s.vf_truth[i] && !r.hit;
      fp += !s.vf_truth[i] && r.hit;
    }
    for (std::size_t i : ee_idx) {
      const CcdResult r = ee_fn(s.ee[i]);
      benchmark::DoNotOptimize(r);
      ++paths[static_cast<int>(r.path)];
      fn += s.ee_truth[i] && !r.hit;
      fp += !s.ee_truth[i] && r.hit;
    }
    n += vf_idx.size() + ee_idx.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
  const double total = static_cast<double>(vf_idx.size() + ee_idx.size());
  state.counters["queries"] = total;
  for (int i = 0; i < kCcdPathCount; ++i) {
    state.counters[std::string(ccd_path_name(static_cast<CcdPath>(i))) + "_rate"] =
        total > 0 ? static_cast<double>(paths[i]) / total : 0.0;
  }
  state.counters["gmp_queries"] = static_cast<double>(paths[static_cast<int>(CcdPath::gmp)]);
  state.counters["false_negatives"] = static_cast<double>(fn);
  state.counters["false_positives"] = static_cast<double>(fp);
  state.counters["ns_per_query"] = benchmark::Counter(
      static_cast<double>(n), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

std::vector<std::size_t> all(std::size_t n) {
  std::vector<std::size_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

void BM_Ccd(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const QuerySet& s = set(k);
  state.SetLabel(set_name(k));
  run_set(
      state, s, all(s.vf.size()), all(s.ee.size()),
      [](const VertexFaceQuery& q) { return vertex_face_ccd(q); },
      [](const EdgeEdgeQuery& q) { return edge_edge_ccd(q); });
}

void BM_CcdTier(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const auto tier = static_cast<CcdPath>(state.range(1));
  const QuerySet& s = set(k);
  state.SetLabel(std::string(set_name(k)) + "/" + ccd_path_name(tier));
  std::vector<std::size_t> vf, ee;
  for (std::size_t i = 0; i < s.vf.size(); ++i) {
    if (vertex_face_ccd(s.vf[i]).path == tier) vf.push_back(i);
  }
  for (std::size_t i = 0; i < s.ee.size(); ++i) {
    if (edge_edge_ccd(s.ee[i]).path == tier) ee.push_back(i);
  }
  if (vf.empty() && ee.empty()) {
    state.SkipWithError("no query of this set is decided by this tier");
    return;
  }
  run_set(
      state, s, vf, ee, [](const VertexFaceQuery& q) { return vertex_face_ccd(q); },
      [](const EdgeEdgeQuery& q) { return edge_edge_ccd(q); });
}

void BM_ExactTier(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const QuerySet& s = set(k);
  state.SetLabel(set_name(k));
  run_set(
      state, s, all(s.vf.size()), all(s.ee.size()),
      [](const VertexFaceQuery& q) { return detail::vertex_face_ccd_exact(q); },
      [](const EdgeEdgeQuery& q) { return detail::edge_edge_ccd_exact(q); });
}

void BM_Naive(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const QuerySet& s = set(k);
  state.SetLabel(set_name(k));
  run_set(
      state, s, all(s.vf.size()), all(s.ee.size()),
      [](const VertexFaceQuery& q) {
        return CcdResult{bench::naive_vertex_face(q), 1.0, CcdPath::double_precision};
      },
      [](const EdgeEdgeQuery& q) {
        return CcdResult{bench::naive_edge_edge(q), 1.0, CcdPath::double_precision};
      });
}

void BM_CoplanaritySign(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const QuerySet& s = set(k);
  state.SetLabel(set_name(k));
  std::size_t n = 0, culled = 0;
  for (auto _ : state) {
    culled = 0;
    for (const auto& q : s.vf) {
      const StepSign r =
          coplanarity_sign({q.a_t0, q.b_t0, q.c_t0, q.p_t0}, {q.a_t1, q.b_t1, q.c_t1, q.p_t1});
      benchmark::DoNotOptimize(r);
      culled += r != StepSign::mixed;
    }
    for (const auto& q : s.ee) {
      const StepSign r = coplanarity_sign({q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0},
                                          {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1});
      benchmark::DoNotOptimize(r);
      culled += r != StepSign::mixed;
    }
    n += s.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
  state.counters["culled_rate"] = static_cast<double>(culled) / static_cast<double>(s.size());
}

void tiers(benchmark::internal::Benchmark* b) {
  for (int k = 0; k <= 5; ++k) {
    for (int tier = 0; tier < kCcdPathCount; ++tier) b->Args({k, tier});
  }
}

BENCHMARK(BM_Ccd)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CcdTier)->Apply(tiers)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExactTier)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Naive)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoplanaritySign)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tailor

BENCHMARK_MAIN();

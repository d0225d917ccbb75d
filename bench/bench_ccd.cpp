/// @file
/// Throughput of the exact CCD (one core) on the reference queries, with the share of
/// queries each path decides, the coplanarity filter alone, and a naive floating-point
/// cubic-solver baseline with its false negatives / positives against the ground truth.

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "naive_ccd.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"
#include "tailor/ccd/query_io.hpp"

namespace tailor {
namespace {

struct QuerySet {
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
  std::vector<bool> vf_truth, ee_truth;
};

const std::string kData = TAILOR_DATA_DIR;
const char* kErleben[] = {
    "cube-cliff-edges", "cube-internal-edges", "sliding-spike", "sliding-wedge", "spike-crack",
    "spike-hole",       "spike-wedge",         "spikes",        "wedge-crack",   "wedges"};

void append(QuerySet& s, const std::string& path, const std::string& truth_json = "") {
  CcdQueryFile f = read_ccd_queries(path);
  std::vector<bool> truth = truth_json.empty() ? f.truth : read_ccd_truth_json(truth_json);
  if (f.kind == CcdQueryKind::vertex_face) {
    s.vf.insert(s.vf.end(), f.vertex_face.begin(), f.vertex_face.end());
    s.vf_truth.insert(s.vf_truth.end(), truth.begin(), truth.end());
  } else {
    s.ee.insert(s.ee.end(), f.edge_edge.begin(), f.edge_edge.end());
    s.ee_truth.insert(s.ee_truth.end(), truth.begin(), truth.end());
  }
}

const QuerySet& funnel() {
  static const QuerySet s = [] {
    QuerySet r;
    const std::string d = kData + "/cloth-funnel";
    append(r, d + "/queries/227vf.csv", d + "/mma_bool/227vf_mma_bool.json");
    append(r, d + "/queries/227ee.csv", d + "/mma_bool/227ee_mma_bool.json");
    return r;
  }();
  return s;
}

const QuerySet& erleben() {
  static const QuerySet s = [] {
    QuerySet r;
    for (const char* name : kErleben) {
      const std::string d = kData + "/ccd-queries/erleben-" + name;
      append(r, d + "/vertex-face/data_0_0.csv");
      append(r, d + "/edge-edge/data_0_0.csv");
    }
    return r;
  }();
  return s;
}

const QuerySet& unit_tests() {
  static const QuerySet s = [] {
    QuerySet r;
    const std::string d = kData + "/ccd-queries/unit-tests";
    for (const char* f : {"vertex-face/data_0_0.csv", "vertex-face/data_0_1.csv",
                          "edge-edge/data_0_0.csv", "edge-edge/data_0_1.csv"}) {
      append(r, d + "/" + f);
    }
    return r;
  }();
  return s;
}

const QuerySet& set(int i) {
  return i == 0 ? funnel() : (i == 1 ? erleben() : unit_tests());
}
const char* set_name(int i) {
  return i == 0 ? "funnel" : (i == 1 ? "erleben" : "unit-tests");
}

template <class Q, class Fn>
void run_exact(benchmark::State& state, const std::vector<Q>& qs, Fn&& fn) {
  std::size_t paths[3] = {0, 0, 0};
  std::size_t n = 0;
  for (auto _ : state) {
    for (const Q& q : qs) {
      const CcdResult r = fn(q);
      benchmark::DoNotOptimize(r);
      ++paths[static_cast<int>(r.path)];
    }
    n += qs.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
  const double total = static_cast<double>(n);
  state.counters["filter_rate"] = static_cast<double>(paths[0]) / total;
  state.counters["double_rate"] = static_cast<double>(paths[1]) / total;
  state.counters["exact_fallback_rate"] = static_cast<double>(paths[2]) / total;
}

void BM_VertexFaceCcd(benchmark::State& state) {
  const QuerySet& s = set(static_cast<int>(state.range(0)));
  state.SetLabel(set_name(static_cast<int>(state.range(0))));
  run_exact(state, s.vf, [](const VertexFaceQuery& q) { return vertex_face_ccd(q); });
}

void BM_EdgeEdgeCcd(benchmark::State& state) {
  const QuerySet& s = set(static_cast<int>(state.range(0)));
  state.SetLabel(set_name(static_cast<int>(state.range(0))));
  run_exact(state, s.ee, [](const EdgeEdgeQuery& q) { return edge_edge_ccd(q); });
}

void BM_CoplanaritySign(benchmark::State& state) {
  const QuerySet& s = set(static_cast<int>(state.range(0)));
  state.SetLabel(set_name(static_cast<int>(state.range(0))));
  std::size_t n = 0, culled = 0;
  for (auto _ : state) {
    for (const auto& q : s.vf) {
      const StepSign r =
          coplanarity_sign(q.a_t0, q.b_t0, q.c_t0, q.p_t0, q.a_t1, q.b_t1, q.c_t1, q.p_t1);
      benchmark::DoNotOptimize(r);
      culled += r != StepSign::mixed;
    }
    for (const auto& q : s.ee) {
      const StepSign r = coplanarity_sign(q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1,
                                          q.ea1_t1, q.eb0_t1, q.eb1_t1);
      benchmark::DoNotOptimize(r);
      culled += r != StepSign::mixed;
    }
    n += s.vf.size() + s.ee.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
  state.counters["culled_rate"] = static_cast<double>(culled) / static_cast<double>(n);
}

template <class Q, class Fn>
void run_naive(benchmark::State& state, const std::vector<Q>& qs, const std::vector<bool>& truth,
               Fn&& fn) {
  std::size_t n = 0, fn_count = 0, fp_count = 0;
  for (auto _ : state) {
    fn_count = fp_count = 0;
    for (std::size_t i = 0; i < qs.size(); ++i) {
      const bool hit = fn(qs[i]);
      benchmark::DoNotOptimize(hit);
      fn_count += truth[i] && !hit;
      fp_count += !truth[i] && hit;
    }
    n += qs.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
  state.counters["false_negatives"] = static_cast<double>(fn_count);
  state.counters["false_positives"] = static_cast<double>(fp_count);
  state.counters["queries"] = static_cast<double>(qs.size());
}

void BM_NaiveVertexFace(benchmark::State& state) {
  const QuerySet& s = set(static_cast<int>(state.range(0)));
  state.SetLabel(set_name(static_cast<int>(state.range(0))));
  run_naive(state, s.vf, s.vf_truth,
            [](const VertexFaceQuery& q) { return bench::naive_vertex_face(q); });
}

void BM_NaiveEdgeEdge(benchmark::State& state) {
  const QuerySet& s = set(static_cast<int>(state.range(0)));
  state.SetLabel(set_name(static_cast<int>(state.range(0))));
  run_naive(state, s.ee, s.ee_truth,
            [](const EdgeEdgeQuery& q) { return bench::naive_edge_edge(q); });
}

// Argument: 0 = cloth-funnel, 1 = erleben scenes, 2 = unit-tests.
BENCHMARK(BM_VertexFaceCcd)->DenseRange(0, 2);
BENCHMARK(BM_EdgeEdgeCcd)->DenseRange(0, 2);
BENCHMARK(BM_CoplanaritySign)->DenseRange(0, 2);
BENCHMARK(BM_NaiveVertexFace)->DenseRange(0, 2);
BENCHMARK(BM_NaiveEdgeEdge)->DenseRange(0, 2);

}  // namespace
}  // namespace tailor

BENCHMARK_MAIN();

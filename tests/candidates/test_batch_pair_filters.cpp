// The batch form of the low-level filters decides exactly as the one-pair filters, pair by
// pair, in every build (two lanes and the widest this processor runs), for every filter
// combination and batch size, on random, near-degenerate, exactly degenerate, extreme-range
// and reference queries.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "support/degenerate_ccd_queries.hpp"
#include "support/sanitized.hpp"
#include "tailor/candidates/batch_pair_filters.hpp"
#include "tailor/ccd/query_io.hpp"

namespace tailor {
namespace {

// One pair: its kind and the points a, b, c, d at t = 0 (0-3) and t = 1 (4-7).
struct Pair {
  PairKind kind = PairKind::vertex_face;
  Vec3 p[8];
};

Pair from(const VertexFaceQuery& q) {
  return {PairKind::vertex_face, {q.a_t0, q.b_t0, q.c_t0, q.p_t0, q.a_t1, q.b_t1, q.c_t1, q.p_t1}};
}

Pair from(const EdgeEdgeQuery& q) {
  return {PairKind::edge_edge,
          {q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1}};
}

PairVerdict one_pair_verdict(const Pair& q, PairFilters filters) {
  const Vec3* p = q.p;
  if (q.kind == PairKind::vertex_face) {
    return vertex_face_verdict({p[3], p[0], p[1], p[2]}, {p[7], p[4], p[5], p[6]}, filters);
  }
  return edge_edge_verdict({p[0], p[1], p[2], p[3]}, {p[4], p[5], p[6], p[7]}, filters);
}

std::vector<Pair> test_pairs() {
  std::vector<Pair> pairs;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cell(-4, 4);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const int trials = testing::sanitized() ? 2000 : 20000;
  for (int trial = 0; trial < trials; ++trial) {
    Pair q;
    q.kind = trial % 2 == 0 ? PairKind::vertex_face : PairKind::edge_edge;
    const bool lattice = trial % 3 == 0;
    for (Vec3& x : q.p) {
      x = lattice ? Vec3(cell(rng), cell(rng), cell(rng)) / 4.0
                  : Vec3(uniform(rng), uniform(rng), uniform(rng));
    }
    if (trial % 4 == 0) {
      for (int i : {0, 1, 2, 4, 5, 6}) q.p[i].z() = 0;  // a plane that stays put
    }
    if (trial % 7 == 0) q.p[7] = q.p[3] + Vec3(0, 0, 1e-9);  // barely moves
    if (trial % 11 == 0) {
      for (Vec3& x : q.p) x *= std::ldexp(1.0, trial % 22 == 0 ? 240 : -240);  // out of range
    }
    pairs.push_back(q);
  }
  testing::DegenerateQueryGenerator degenerate(11);
  for (int i = 0; i < trials / 4; ++i) {
    const testing::DegenerateQuery d = degenerate.next();
    pairs.push_back(d.vertex_face ? from(d.vf) : from(d.ee));
  }
  const std::string dir = std::string(TAILOR_DATA_DIR) + "/ccd-queries";
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".csv") continue;
    const CcdQueryFile file = read_ccd_queries(entry.path().string());
    for (const VertexFaceQuery& q : file.vertex_face) pairs.push_back(from(q));
    for (const EdgeEdgeQuery& q : file.edge_edge) pairs.push_back(from(q));
  }
  return pairs;
}

using BatchVerdicts = void (*)(PairKind, PairBatch&, PairFilters,
                               std::span<PairVerdict, PairBatch::kCapacity>);

// Runs `batch_verdicts` over `pairs` of one kind in batches of `size` and checks every
// verdict; returns how many of each verdict the batches gave.
std::array<int, 3> expect_same_verdicts(BatchVerdicts batch_verdicts,
                                        const std::vector<Pair>& pairs, PairKind kind,
                                        PairFilters filters, int size) {
  std::array<int, 3> seen{};
  std::vector<const Pair*> of_kind;
  for (const Pair& q : pairs) {
    if (q.kind == kind) of_kind.push_back(&q);
  }
  for (std::size_t first = 0; first < of_kind.size(); first += static_cast<std::size_t>(size)) {
    PairBatch batch;
    const std::size_t end = std::min(of_kind.size(), first + static_cast<std::size_t>(size));
    for (std::size_t i = first; i < end; ++i) {
      const Vec3* p = of_kind[i]->p;
      batch.add(static_cast<Index>(i), 0, {p[0].data(), p[1].data(), p[2].data(), p[3].data()},
                {p[4].data(), p[5].data(), p[6].data(), p[7].data()});
    }
    std::array<PairVerdict, PairBatch::kCapacity> verdicts;
    batch_verdicts(kind, batch, filters, verdicts);
    for (int lane = 0; lane < batch.count; ++lane) {
      const Pair& q = *of_kind[first + static_cast<std::size_t>(lane)];
      const PairVerdict expected = one_pair_verdict(q, filters);
      EXPECT_EQ(verdicts[static_cast<std::size_t>(lane)], expected)
          << (kind == PairKind::vertex_face ? "VF" : "EE") << " pair " << first + lane
          << " in a batch of " << size;
      ++seen[static_cast<std::size_t>(verdicts[static_cast<std::size_t>(lane)])];
    }
  }
  return seen;
}

TEST(BatchPairFilters, VerdictsEqualTheOnePairFiltersInEveryBuild) {
  const std::vector<Pair> pairs = test_pairs();
  for (BatchVerdicts verdicts : {&pair_verdicts, &detail::pair_verdicts_two_lanes}) {
    for (PairFilters filters :
         {PairFilters{true, true}, PairFilters{true, false}, PairFilters{false, true}}) {
      for (PairKind kind : {PairKind::vertex_face, PairKind::edge_edge}) {
        for (int size : {16, 13, 5, 1}) {
          const std::array<int, 3> seen =
              expect_same_verdicts(verdicts, pairs, kind, filters, size);
          // Every verdict the filters allow occurs, so each path was exercised.
          if (filters.coplanarity) {
            EXPECT_GT(seen[0], 0);
          }
          if (filters.projection) {
            EXPECT_GT(seen[1], 0);
          }
          EXPECT_GT(seen[2], 0);
        }
      }
    }
  }
}

}  // namespace
}  // namespace tailor

#include "tailor/detection/exact_pair_tests.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <optional>
#include <type_traits>
#include <vector>

#include "tailor/ccd/thickness_ccd.hpp"
#include "tailor/ccd/ccd.hpp"

namespace tailor {
namespace {

// The CCD of either pair kind, by overload.
CcdResult touching_ccd(const VertexFaceQuery& q) {
  return vertex_face_ccd(q);
}
CcdResult touching_ccd(const EdgeEdgeQuery& q) {
  return edge_edge_ccd(q);
}

// The query of a pair at the step from x0 to x1.
VertexFaceQuery query_of(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                         const VertexFacePair& pair) {
  const auto [v, f] = pair;
  const Index a = mesh.faces()(f, 0), b = mesh.faces()(f, 1), c = mesh.faces()(f, 2);
  return {x0.row(v), x0.row(a), x0.row(b), x0.row(c), x1.row(v), x1.row(a), x1.row(b), x1.row(c)};
}
EdgeEdgeQuery query_of(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                       const EdgeEdgePair& pair) {
  const auto [e1, e2] = pair;
  const Index a = mesh.edges()(e1, 0), b = mesh.edges()(e1, 1);
  const Index c = mesh.edges()(e2, 0), d = mesh.edges()(e2, 1);
  return {x0.row(a), x0.row(b), x0.row(c), x0.row(d), x1.row(a), x1.row(b), x1.row(c), x1.row(d)};
}

EdgeEdgeCollision make_edge_edge(const EdgeArray& edges, Index e1, Index e2, double toi) {
  // Edges are stored (a, b) with a < b; order the two edges by their vertex ids.
  if (std::pair(edges(e2, 0), edges(e2, 1)) < std::pair(edges(e1, 0), edges(e1, 1))) {
    std::swap(e1, e2);
  }
  return {edges(e1, 0), edges(e1, 1), edges(e2, 0), edges(e2, 1), e1, e2, toi};
}

// In parallel: a contact-heavy step has about one collision per triangle, and a serial
// sort of them was the largest part of the exact-CCD stage that did not scale with
// threads (folded cloth, 1M triangles).
template <class T>
void sort_unique(std::vector<T>& items) {
  tbb::parallel_sort(items.begin(), items.end());
  items.erase(std::unique(items.begin(), items.end(),
                          [](const T& a, const T& b) { return !(a < b) && !(b < a); }),
              items.end());
}

}  // namespace

void ExactPairTester::begin_step() {
  for (ThreadOutput& out : m_outputs) {
    out.vertex_face.clear();
    out.edge_edge.clear();
    out.exact = 0;
  }
}

void ExactPairTester::test(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                           std::span<const VertexFacePair> vertex_face,
                           std::span<const EdgeEdgePair> edge_edge) {
  const std::span<const VertexFacePair> vf_blocks[1] = {vertex_face};
  const std::span<const EdgeEdgePair> ee_blocks[1] = {edge_edge};
  test(mesh, x0, x1, vf_blocks, ee_blocks);
}

void ExactPairTester::test(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                           std::span<const std::span<const VertexFacePair>> vertex_face_blocks,
                           std::span<const std::span<const EdgeEdgePair>> edge_edge_blocks) {
  // One task per chunk of a block: VF chunks first, then EE chunks.
  struct Chunk {
    bool edge_edge;
    std::size_t block, begin, end;
  };
  std::vector<Chunk> chunks;
  // With a thickness, chunks as large as leave about eight per thread.
  std::size_t total = 0;
  for (const auto& block : vertex_face_blocks) total += block.size();
  for (const auto& block : edge_edge_blocks) total += block.size();
  const auto threads = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
  const std::size_t pairs =
      m_thickness > 0 ? std::clamp(total / (8 * threads), kChunkPairs, kThicknessChunkPairs)
                      : kChunkPairs;
  const auto add_chunks = [&](bool edge_edge, std::size_t block, std::size_t size) {
    for (std::size_t begin = 0; begin < size; begin += pairs) {
      chunks.push_back({edge_edge, block, begin, std::min(size, begin + pairs)});
    }
  };
  for (std::size_t b = 0; b < vertex_face_blocks.size(); ++b) {
    add_chunks(false, b, vertex_face_blocks[b].size());
  }
  for (std::size_t b = 0; b < edge_edge_blocks.size(); ++b) {
    add_chunks(true, b, edge_edge_blocks[b].size());
  }
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t k) {
    const Chunk& chunk = chunks[k];
    ThreadOutput& out = m_outputs.local();
    const auto run = [&](const auto& block) {
      const auto pairs = block.subspan(chunk.begin, chunk.end - chunk.begin);
      if (m_thickness > 0) {
        within_thickness(mesh, x0, x1, pairs, out);
      } else {
        touching(mesh, x0, x1, pairs, out);
      }
    };
    if (chunk.edge_edge) {
      run(edge_edge_blocks[chunk.block]);
    } else {
      run(vertex_face_blocks[chunk.block]);
    }
  });
}

template <class Pair>
void ExactPairTester::touching(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                               std::span<const Pair> pairs, ThreadOutput& out) const {
  for (const Pair& pair : pairs) {
    if (const auto toi = time_of_impact(query_of(mesh, x0, x1, pair), out.exact)) {
      record(out, pair, *toi);
    }
  }
}

template <class Pair>
void ExactPairTester::within_thickness(const TriangleMesh& mesh, const Positions& x0,
                                       const Positions& x1, std::span<const Pair> pairs,
                                       ThreadOutput& out) const {
  // The whole chunk at once: the advancements run in vector lanes (ccd/advance_lanes.hpp).
  auto& queries = queries_in(out, pairs);
  queries.clear();
  for (const Pair& pair : pairs) queries.push_back(query_of(mesh, x0, x1, pair));
  std::vector<ThicknessResult>& results = out.results;
  results.resize(pairs.size());
  if constexpr (std::is_same_v<Pair, VertexFacePair>) {
    vertex_face_ccd_within(queries, m_thickness, m_normal_test, results);
  } else {
    edge_edge_ccd_within(queries, m_thickness, m_normal_test, results);
  }
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (results[i].hit) record(out, pairs[i], results[i].toi);
  }
}

template <class Query>
std::optional<double> ExactPairTester::time_of_impact(const Query& query,
                                                      std::int64_t& exact) const {
  const CcdResult result = touching_ccd(query);
  exact += result.path == CcdPath::exact || result.path == CcdPath::gmp;
  return result.hit ? std::optional<double>(result.toi) : std::nullopt;
}

CollisionSet ExactPairTester::take_collisions(const TriangleMesh& mesh) {
  CollisionSet all;
  auto gather = [&](auto result_member, auto thread_member, const auto& convert) {
    auto& result = all.*result_member;
    std::size_t total = 0;
    for (const ThreadOutput& out : m_outputs) total += (out.*thread_member).size();
    result.reserve(total);
    for (ThreadOutput& out : m_outputs) {
      auto& mine = out.*thread_member;
      // Front to back, so that each block is freed once copied.
      for (; !mine.empty(); mine.pop_front()) result.push_back(convert(mine.front()));
      std::remove_reference_t<decltype(mine)>().swap(mine);
    }
    sort_unique(result);
  };
  gather(&CollisionSet::vertex_face, &ThreadOutput::vertex_face,
         [](const VertexFaceCollision& c) { return c; });
  gather(&CollisionSet::edge_edge, &ThreadOutput::edge_edge, [&](const EdgeEdgeHit& hit) {
    return make_edge_edge(mesh.edges(), hit.e1, hit.e2, hit.toi);
  });
  return all;
}

std::int64_t ExactPairTester::exact_fallbacks() const {
  std::int64_t total = 0;
  for (const ThreadOutput& out : m_outputs) total += out.exact;
  return total;
}

CollisionSet test_pairs_exactly(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                                CandidateBatch batch, double thickness,
                                std::int64_t* exact_fallbacks) {
  ExactPairTester tester;
  tester.set_thickness(thickness);
  tester.test(mesh, x0, x1, batch.vertex_face, batch.edge_edge);
  if (exact_fallbacks != nullptr) *exact_fallbacks = tester.exact_fallbacks();
  return tester.take_collisions(mesh);
}

}  // namespace tailor

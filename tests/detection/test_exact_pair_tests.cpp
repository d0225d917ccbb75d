// ExactPairTester: every pair of a small folded cloth through it gives exactly the
// brute-force collisions, however the pairs are cut into blocks and at one and two threads.

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <tuple>
#include <vector>

#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/exact_pair_tests.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

using VfList = std::vector<std::tuple<Index, Index, double>>;
using EeList = std::vector<std::tuple<Index, Index, Index, Index, double>>;

VfList vf_list(const CollisionSet& s) {
  VfList list;
  for (const auto& c : s.vertex_face) list.emplace_back(c.vertex, c.face, c.toi);
  return list;
}

EeList ee_list(const CollisionSet& s) {
  EeList list;
  for (const auto& c : s.edge_edge) list.emplace_back(c.a0, c.a1, c.b0, c.b1, c.toi);
  return list;
}

// Cuts `pairs` into consecutive blocks of the given sizes (the last takes the rest).
template <class Pair>
std::vector<std::span<const Pair>> cut(const std::vector<Pair>& pairs,
                                       const std::vector<std::size_t>& sizes) {
  std::vector<std::span<const Pair>> blocks;
  std::size_t first = 0;
  for (const std::size_t size : sizes) {
    const std::size_t n = std::min(size, pairs.size() - first);
    blocks.emplace_back(pairs.data() + first, n);
    first += n;
  }
  blocks.emplace_back(pairs.data() + first, pairs.size() - first);
  return blocks;
}

TEST(ExactPairTester, EveryPairInBlocksGivesTheBruteForceCollisions) {
  const ProceduralStep step = make_folded_cloth_on_sphere(600);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  std::vector<VertexFacePair> vertex_face;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    for (Index f = 0; f < mesh.num_faces(); ++f) {
      if (mesh.faces()(f, 0) != v && mesh.faces()(f, 1) != v && mesh.faces()(f, 2) != v) {
        vertex_face.push_back({v, f});
      }
    }
  }
  std::vector<EdgeEdgePair> edge_edge;
  const EdgeArray& edges = mesh.edges();
  for (Index a = 0; a < mesh.num_edges(); ++a) {
    for (Index b = a + 1; b < mesh.num_edges(); ++b) {
      if (edges(a, 0) != edges(b, 0) && edges(a, 0) != edges(b, 1) && edges(a, 1) != edges(b, 0) &&
          edges(a, 1) != edges(b, 1)) {
        edge_edge.push_back({a, b});
      }
    }
  }
  const CollisionSet expected = brute_force_self_collisions(mesh, step.x0, step.x1);
  ASSERT_GT(expected.vertex_face.size(), std::size_t{20});
  ASSERT_GT(expected.edge_edge.size(), std::size_t{20});

  for (const int threads : {1, 2}) {
    tbb::task_arena(threads).execute([&] {
      // Blocks of every kind: empty, shorter than a chunk, one chunk, one over, many.
      const std::vector<std::size_t> sizes = {0,
                                              1,
                                              ExactPairTester::kChunkPairs - 1,
                                              ExactPairTester::kChunkPairs,
                                              ExactPairTester::kChunkPairs + 1,
                                              0,
                                              5000};
      ExactPairTester tester;
      tester.begin_step();
      tester.test(mesh, step.x0, step.x1, cut(vertex_face, sizes), cut(edge_edge, {}));
      // A second call in the same step adds to the first (here: nothing new).
      tester.test(mesh, step.x0, step.x1, std::span<const VertexFacePair>{},
                  std::span(edge_edge).first(100));
      const CollisionSet blocks = tester.take_collisions(mesh);
      EXPECT_EQ(vf_list(blocks), vf_list(expected)) << threads << " threads";
      EXPECT_EQ(ee_list(blocks), ee_list(expected)) << threads << " threads";

      const CollisionSet one_batch =
          test_pairs_exactly(mesh, step.x0, step.x1, {vertex_face, edge_edge});
      EXPECT_EQ(vf_list(one_batch), vf_list(expected)) << threads << " threads";
      EXPECT_EQ(ee_list(one_batch), ee_list(expected)) << threads << " threads";
    });
  }
}

}  // namespace
}  // namespace tailor

// The candidate traversal: without cones it finds exactly the leaf pairs whose bounds may meet
// (brute force); its block lists: consume() hands over exactly the pairs blocks() shows,
// leaves none behind, and a traversal after it (its blocks freed) finds the same pairs again;
// remove_if() removes exactly the pairs its test culls; at one and two threads.

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/culling/bvh_traversal.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

using PairList = std::vector<std::pair<Index, Index>>;

PairList sorted(const std::vector<TrianglePair>& pairs) {
  PairList list;
  for (const TrianglePair& p : pairs) list.emplace_back(p.first, p.second);
  std::sort(list.begin(), list.end());
  return list;
}

TEST(CandidateTraversal, ConsumeHandsOverEveryPairOnceAndFreesTheBlocks) {
  // A folded cloth of ~100K triangles: several 256 KiB blocks of pairs per thread.
  const ProceduralStep step = make_folded_cloth_on_sphere(100'000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  for (const int threads : {1, 2}) {
    tbb::task_arena(threads).execute([&] {
      const MeshBvh bvh = [&] {
        MeshBvh tree(mesh, step.x0);
        tree.refit(step.x0, step.x1, true);
        return tree;
      }();
      const NodeContours contours(mesh, bvh);
      CandidateTraversal traversal(mesh);
      traversal.self(bvh, contours, {step.x0, step.x1}, {});
      std::vector<TrianglePair> shown;
      for (const auto block : traversal.blocks())
        shown.insert(shown.end(), block.begin(), block.end());
      ASSERT_GT(shown.size(), std::size_t{100'000}) << "too few pairs to fill several blocks";

      std::vector<TrianglePair> consumed;
      int blocks = 0;
      traversal.consume([&](std::span<const TrianglePair> block) {
        consumed.insert(consumed.end(), block.begin(), block.end());
        ++blocks;
      });
      EXPECT_GT(blocks, 2);
      EXPECT_EQ(sorted(consumed), sorted(shown)) << threads << " threads";
      EXPECT_EQ(traversal.size(), 0);
      EXPECT_TRUE(traversal.blocks().empty());

      traversal.clear();
      traversal.self(bvh, contours, {step.x0, step.x1}, {});
      std::vector<TrianglePair> again;
      for (const auto block : traversal.blocks())
        again.insert(again.end(), block.begin(), block.end());
      EXPECT_EQ(sorted(again), sorted(shown)) << threads << " threads";
    });
  }
}

// Without cones the walk's candidates are the leaf pairs whose bounds may meet (and share no
// vertex, with adjacency culling), found here pair by pair from the node records: the leaf
// buckets (leaf bounds compared sixteen or eight at a time, in leaf order) must find each and
// no other, with the diagonals and without them, on a folded cloth and on pleats.
TEST(CandidateTraversal, SelfFindsEveryLeafPairThatMayMeet) {
  for (const bool pleated : {false, true}) {
    const ProceduralStep step =
        pleated ? make_pleated_cloth(1'500) : make_folded_cloth_on_sphere(2'500);
    const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
    MeshBvh bvh(mesh, step.x0);
    std::vector<Index> leaves;
    for (Index node = 0; node < bvh.num_nodes(); ++node) {
      if (bvh.is_leaf(node)) leaves.push_back(node);
    }
    for (const bool diagonals : {true, false}) {
      bvh.refit(step.x0, step.x1, false, diagonals);
      for (const bool adjacency : {true, false}) {
        PairList expected;
        for (std::size_t i = 0; i < leaves.size(); ++i) {
          for (std::size_t j = i + 1; j < leaves.size(); ++j) {
            const Index f = bvh.leaf_face(leaves[i]), g = bvh.leaf_face(leaves[j]);
            if (adjacency && mesh.faces_share_vertex(f, g)) continue;
            if (bvh.may_meet(leaves[i], bvh, leaves[j])) {
              expected.emplace_back(std::min(f, g), std::max(f, g));
            }
          }
        }
        std::sort(expected.begin(), expected.end());
        CandidateTraversal traversal(mesh);
        traversal.self(
            bvh, NodeContours{}, {step.x0, step.x1},
            {.normal_cones = false, .contour_test = false, .adjacency_culling = adjacency});
        std::vector<TrianglePair> found;
        for (const auto block : traversal.blocks())
          found.insert(found.end(), block.begin(), block.end());
        EXPECT_EQ(sorted(found), expected)
            << (pleated ? "pleats" : "folded cloth") << ", diagonals " << diagonals
            << ", adjacency culling " << adjacency;
        EXPECT_GT(traversal.counts().leaf_buckets, 0);
        // Some leaf pairs meet, most do not: the test can tell a bucket that drops or adds.
        EXPECT_GT(expected.size(), leaves.size());
        EXPECT_LT(expected.size(), leaves.size() * leaves.size() / 8);
      }
    }
  }
}

TEST(CandidateTraversal, CertifyRootAgreesWithSelfAndNeedsNoBoxes) {
  // certify_root() gives self()'s answer about the root, counts its contour test as self()
  // does and adds no pair; it runs on masks alone, while self() refuses stale boxes.
  const ProceduralStep crumpling = make_crumpling_cloth_step(5000);
  const ProceduralStep folded = make_folded_cloth_on_sphere(1200);
  for (const ProceduralStep* step : {&crumpling, &folded}) {
    const bool certifiable = step == &crumpling;
    const TriangleMesh mesh(static_cast<Index>(step->x0.rows()), step->faces);
    MeshBvh bvh(mesh, step->x0);
    const NodeContours contours(mesh, bvh);
    bvh.refit_directions(step->x0, step->x1);
    CandidateTraversal traversal(mesh);
    EXPECT_EQ(traversal.certify_root(bvh, contours, {step->x0, step->x1}, {}), certifiable);
    EXPECT_EQ(traversal.size(), 0);
    const TraversalCounts root_counts = traversal.counts();
    EXPECT_EQ(root_counts.contour_tests, certifiable ? 1 : 0);
    EXPECT_EQ(root_counts.nodes_culled_by_cones, certifiable ? 1 : 0);
    traversal.clear();
    EXPECT_THROW(traversal.self(bvh, contours, {step->x0, step->x1}, {}), std::logic_error);

    bvh.refit(step->x0, step->x1, false);
    traversal.clear();
    EXPECT_EQ(traversal.self(bvh, contours, {step->x0, step->x1}, {}), certifiable);
    if (certifiable) {
      EXPECT_EQ(traversal.size(), 0);
      EXPECT_EQ(traversal.counts().contour_tests, 1);
    } else {
      EXPECT_GT(traversal.size(), 0);
    }
  }
}

TEST(CandidateTraversal, RemoveIfRemovesExactlyThePairsItsTestCulls) {
  // Several blocks per thread, each cut into many chunks; the test culls two pairs in three.
  const ProceduralStep step = make_folded_cloth_on_sphere(100'000);
  const TriangleMesh mesh(static_cast<Index>(step.x0.rows()), step.faces);
  const auto culled = [](const TrianglePair& p) { return (p.first + 7 * p.second) % 3 != 0; };
  for (const int threads : {1, 2}) {
    tbb::task_arena(threads).execute([&] {
      MeshBvh bvh(mesh, step.x0);
      bvh.refit(step.x0, step.x1, true);
      const NodeContours contours(mesh, bvh);
      CandidateTraversal traversal(mesh);
      traversal.self(bvh, contours, {step.x0, step.x1}, {});
      std::vector<TrianglePair> before, expected;
      for (const auto block : traversal.blocks())
        before.insert(before.end(), block.begin(), block.end());
      std::copy_if(before.begin(), before.end(), std::back_inserter(expected),
                   [&](const TrianglePair& p) { return !culled(p); });
      ASSERT_GT(before.size(), std::size_t{100'000});

      const std::int64_t removed = traversal.remove_if(culled);
      EXPECT_EQ(removed, static_cast<std::int64_t>(before.size() - expected.size()));
      std::vector<TrianglePair> after;
      for (const auto block : traversal.blocks())
        after.insert(after.end(), block.begin(), block.end());
      EXPECT_EQ(sorted(after), sorted(expected)) << threads << " threads";
      EXPECT_EQ(traversal.size(), static_cast<std::int64_t>(expected.size()));
      // Nothing left to remove: a second pass with the same test removes nothing.
      EXPECT_EQ(traversal.remove_if(culled), 0);
    });
  }
}

}  // namespace
}  // namespace tailor

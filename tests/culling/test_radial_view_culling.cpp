// Radial-view culling against brute force on random bending and folding tubes: no culled
// pair of faces ever holds a real collision, the detector's collision sets are brute
// force's, and the culling does cut.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "culling/radial_view_checks.hpp"
#include "culling/radial_view_tubes.hpp"
#include "support/sanitized.hpp"
#include "tailor/culling/radial_view_culling.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/self_collision_detector.hpp"

namespace tailor {
namespace {

using testing::culled_colliding_pairs;
using testing::expect_same_collisions;
using testing::random_folding_tube;
using testing::sanitized;
using testing::TubeStep;

// Fig. 1's "+ radial view" stage: normal cones and radial view, no isolated set.
DetectionConfig cones_and_radial_view() {
  DetectionConfig config = DetectionConfig::preset("basic");
  config.normal_cones = config.contour_test = config.radial_view = true;
  config.keep_candidate_pairs = true;
  return config;
}

TEST(RadialViewCulling, FoldingTubesNeverLoseACollision) {
  // Under the sanitizers every sixth seed (7 of 40): the sample still holds tubes whose
  // clusters are certified whole (seeds 6, 13-17, 26-28, ... in release), so every
  // assertion below stays live.
  const int stride = sanitized() ? 6 : 1;
  std::int64_t collisions = 0, ctps_before = 0, ctps_after = 0, clean = 0, certified = 0;
  for (int seed = 0; seed < 40; seed += stride) {
    SCOPED_TRACE(seed);
    const TubeStep step = random_folding_tube(static_cast<unsigned>(seed));
    const Positions& x0 = step.mesh.vertices;
    const TriangleMesh mesh(static_cast<Index>(x0.rows()), step.mesh.faces);
    const CollisionSet truth = brute_force_self_collisions(mesh, x0, step.x1);
    collisions += static_cast<std::int64_t>(truth.size());

    RadialViewCulling radial(mesh, x0, step.loops);
    const RadialViewCounts counts = radial.classify(x0, step.x1);
    clean += counts.faces_clean;
    certified += counts.clusters_certified;
    EXPECT_EQ(culled_colliding_pairs(mesh, truth, radial), 0);

    DetectionConfig tang = DetectionConfig::preset("tang");
    tang.keep_candidate_pairs = true;
    SelfCollisionDetector without(mesh, x0, tang);
    std::vector<TrianglePair> pairs = without.detect(x0, step.x1).candidate_triangle_pairs;
    ctps_before += static_cast<std::int64_t>(pairs.size());
    radial.cull(pairs);
    ctps_after += static_cast<std::int64_t>(pairs.size());

    for (const DetectionConfig& config :
         {DetectionConfig::preset("paper"), cones_and_radial_view()}) {
      SelfCollisionDetector detector(mesh, x0, config, step.loops);
      expect_same_collisions(detector.detect(x0, step.x1).collisions, truth, "detector");
    }
  }
  // The scenes do collide, and the culling does cut (more than half of Tang's pairs, and
  // some faces are clean and some clusters whole).
  EXPECT_GT(collisions, 100);
  EXPECT_LT(2 * ctps_after, ctps_before);
  EXPECT_GT(clean, 0);
  EXPECT_GT(certified, 0);
}

// The pairs the lazy way culls (radial_view_culling.hpp: edge planes first, then only the
// wanted clusters classified), in input order.
std::vector<char> lazily_culled(RadialViewCulling& radial, const std::vector<TrianglePair>& pairs,
                                const Positions& x0, const Positions& x1, bool find_clean,
                                RadialViewCounts& counts) {
  radial.begin_step(x0, x1, find_clean);
  std::vector<char> culled(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    culled[i] = radial.edge_planes_separate(pairs[i].first, pairs[i].second);
  }
  counts = radial.classify_wanted();
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!culled[i]) culled[i] = 2 * radial.classified_clean(pairs[i].first, pairs[i].second);
  }
  return culled;
}

TEST(RadialViewCulling, LazyWayCullsExactlyWhatFullClassificationCulls) {
  // Candidates with and without shared vertices (clean faces on and off), on tubes whose
  // clusters are certified, partly clean, or neither. One object serves both ways, in
  // both orders, so state left by one step cannot leak into the next.
  const int stride = sanitized() ? 6 : 1;
  std::int64_t by_planes = 0, by_classification = 0, pairs_seen = 0;
  std::int64_t classified_lazily = 0, classified_fully = 0;
  for (int seed = 0; seed < 40; seed += stride) {
    SCOPED_TRACE(seed);
    const TubeStep step = random_folding_tube(static_cast<unsigned>(seed));
    const Positions& x0 = step.mesh.vertices;
    const TriangleMesh mesh(static_cast<Index>(x0.rows()), step.mesh.faces);
    RadialViewCulling radial(mesh, x0, step.loops);
    for (const bool find_clean : {false, true}) {
      DetectionConfig config = DetectionConfig::preset(find_clean ? "basic" : "tang");
      config.normal_cones = config.contour_test = true;
      config.keep_candidate_pairs = true;
      SelfCollisionDetector traversal(mesh, x0, config);
      const std::vector<TrianglePair> pairs =
          traversal.detect(x0, step.x1).candidate_triangle_pairs;
      pairs_seen += static_cast<std::int64_t>(pairs.size());
      for (int order = 0; order < 2; ++order) {  // lazy then full, full then lazy
        RadialViewCounts lazy_counts;
        std::vector<char> lazy;
        if (order == 0) lazy = lazily_culled(radial, pairs, x0, step.x1, find_clean, lazy_counts);
        const RadialViewCounts full_counts = radial.classify(x0, step.x1, find_clean);
        std::vector<char> full(pairs.size());
        for (std::size_t i = 0; i < pairs.size(); ++i) {
          full[i] = radial.pair_culled(pairs[i].first, pairs[i].second);
        }
        if (order == 1) lazy = lazily_culled(radial, pairs, x0, step.x1, find_clean, lazy_counts);
        for (std::size_t i = 0; i < pairs.size(); ++i) {
          ASSERT_EQ(lazy[i] != 0, full[i] != 0)
              << "pair " << pairs[i].first << " " << pairs[i].second << " clean " << find_clean;
          by_planes += lazy[i] == 1;
          by_classification += lazy[i] == 2;
        }
        classified_lazily += lazy_counts.clusters_classified;
        classified_fully += full_counts.clusters_classified;
      }
    }
  }
  // Both rules cut, and the lazy way classified fewer clusters than the full one.
  EXPECT_GT(pairs_seen, 0);
  EXPECT_GT(by_planes, 0);
  EXPECT_GT(by_classification, 0);
  EXPECT_LT(classified_lazily, classified_fully);
}

TEST(RadialViewCulling, CulledPairsAreASubsetOfTheTraversal) {
  // Radial view only removes pairs: the detector's CTPs with it are the CTPs without it
  // minus the culled ones, never a pair the traversal did not produce.
  const TubeStep step = random_folding_tube(7);
  const Positions& x0 = step.mesh.vertices;
  const TriangleMesh mesh(static_cast<Index>(x0.rows()), step.mesh.faces);
  DetectionConfig with = cones_and_radial_view();
  DetectionConfig without = with;
  without.radial_view = false;
  SelfCollisionDetector a(mesh, x0, with, step.loops), b(mesh, x0, without, step.loops);
  const auto key = [](const TrianglePair& p) { return std::pair{p.first, p.second}; };
  std::set<std::pair<Index, Index>> all;
  for (const TrianglePair& p : b.detect(x0, step.x1).candidate_triangle_pairs) all.insert(key(p));
  const std::vector<TrianglePair> kept = a.detect(x0, step.x1).candidate_triangle_pairs;
  EXPECT_LT(kept.size(), all.size());
  for (const TrianglePair& p : kept) EXPECT_TRUE(all.count(key(p))) << p.first << " " << p.second;
}

TEST(RadialViewCulling, ObserverOutsideTheTubeCertifiesNothing) {
  // A U-bent tube whose section loop takes a vertex from each leg: the observer lies in
  // the gap between the legs, outside the tube. Its cluster (the whole tube) has winding
  // number 0, so no face is clean; only edge-plane separations may cut, and the results
  // still equal brute force.
  using testing::kTubeRings;
  using testing::kTubeSegments;
  TubeStep step{
      make_tube(kTubeRings, kTubeSegments, testing::kTubeRadius, testing::kTubeLength), {}, {}};
  const Positions straight = step.mesh.vertices;
  step.mesh.vertices = testing::bend(straight, M_PI, 0.7, testing::kTubeLength);
  step.x1 = testing::bend(straight, 1.05 * M_PI, 0.7, testing::kTubeLength);
  const std::vector<std::vector<Index>> outside{
      {2 * kTubeSegments, (kTubeRings - 3) * kTubeSegments}};
  const Positions& x0 = step.mesh.vertices;
  const TriangleMesh mesh(static_cast<Index>(x0.rows()), step.mesh.faces);
  RadialViewCulling radial(mesh, x0, outside);
  const RadialViewCounts counts = radial.classify(x0, step.x1);
  EXPECT_EQ(counts.clusters_used, 0);
  EXPECT_EQ(counts.faces_clean, 0);
  const CollisionSet truth = brute_force_self_collisions(mesh, x0, step.x1);
  EXPECT_EQ(culled_colliding_pairs(mesh, truth, radial), 0);
  SelfCollisionDetector detector(mesh, x0, DetectionConfig::preset("paper"), outside);
  expect_same_collisions(detector.detect(x0, step.x1).collisions, truth, "outside observer");
}

}  // namespace
}  // namespace tailor

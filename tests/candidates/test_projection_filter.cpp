// The projection filter never drops a contact: checked against the ground truth of the
// reference CCD queries and against the exact CCD on random and degenerate queries; and
// it does drop the pairs it is made for (a vertex crossing a face's plane beside it,
// edges crossing each other's plane side by side, coplanar pairs sliding apart).

#include "support/sanitized.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "tailor/candidates/projection_filter.hpp"
#include "tailor/ccd/ccd.hpp"
#include "tailor/ccd/query_io.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {
namespace {

using tailor::testing::sanitized;

bool keeps(const VertexFaceQuery& q) {
  return vertex_face_may_touch_in_projection({q.p_t0, q.a_t0, q.b_t0, q.c_t0},
                                             {q.p_t1, q.a_t1, q.b_t1, q.c_t1});
}

bool keeps(const EdgeEdgeQuery& q) {
  return edge_edge_may_touch_in_projection({q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0},
                                           {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1});
}

Vec3 scaled(const Vec3& x, int e) {
  return {std::ldexp(x[0], e), std::ldexp(x[1], e), std::ldexp(x[2], e)};
}

TEST(ProjectionFilter, KeepsEveryCollidingReferenceQuery) {
  const std::string dir = std::string(TAILOR_DATA_DIR) + "/ccd-queries";
  std::int64_t colliding = 0, culled = 0, total = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".csv") continue;
    const CcdQueryFile file = read_ccd_queries(entry.path().string());
    ASSERT_EQ(file.truth.size(), file.size()) << entry.path();
    for (std::size_t i = 0; i < file.size(); ++i) {
      // Scaling by powers of two must not change the verdict on a contact.
      for (int e : {0, -40, 40}) {
        bool kept = false;
        if (file.kind == CcdQueryKind::vertex_face) {
          VertexFaceQuery q = file.vertex_face[i];
          for (Vec3* x : {&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1}) {
            *x = scaled(*x, e);
          }
          kept = keeps(q);
        } else {
          EdgeEdgeQuery q = file.edge_edge[i];
          for (Vec3* x : {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1,
                          &q.eb0_t1, &q.eb1_t1}) {
            *x = scaled(*x, e);
          }
          kept = keeps(q);
        }
        if (file.truth[i]) {
          ASSERT_TRUE(kept) << entry.path() << " query " << i << " scaled 2^" << e;
        } else if (e == 0) {
          culled += kept ? 0 : 1;
        }
      }
      colliding += file.truth[i] ? 1 : 0;
      ++total;
    }
  }
  EXPECT_GT(colliding, 300);
  EXPECT_GT(culled, 0);  // it does cut non-colliding reference queries
  RecordProperty("culled_non_colliding", static_cast<int>(culled));
}

// Random queries on a coarse dyadic lattice (exact touches, coplanar motion and parallel
// edges are common) and near contacts: every hit of the exact CCD must be kept.
TEST(ProjectionFilter, KeepsEveryHitOfTheExactCcdOnRandomQueries) {
  std::mt19937 rng(2024);
  const int trials = sanitized() ? 3000 : 60000;
  std::int64_t hits = 0, culled_by_projection_only = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const bool lattice = trial % 2 == 0;
    std::uniform_int_distribution<int> cell(-4, 4);
    std::uniform_real_distribution<double> uniform(-1, 1);
    auto point = [&] {
      return lattice ? Vec3(cell(rng), cell(rng), cell(rng)) / 4.0
                     : Vec3(uniform(rng), uniform(rng), uniform(rng));
    };
    // A triangle / edge near z = 0 crossed by points moving through it.
    Vec3 p[8];
    for (Vec3& x : p) x = point();
    if (trial % 3 == 0) {
      for (int i : {1, 2, 3, 5, 6, 7}) p[i].z() = 0;  // coplanar all step
    }
    if (trial % 5 == 0) p[4] = p[0] + (lattice ? Vec3(0, 0, 0.25) : Vec3(0, 0, 0.01));
    if (trial % 2 == 0) {
      const VertexFaceQuery q{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
      const bool hit = vertex_face_ccd(q).hit;
      hits += hit;
      if (hit) {
        ASSERT_TRUE(keeps(q)) << "VF trial " << trial;
      }
      if (!keeps(q) &&
          may_become_coplanar({q.a_t0, q.b_t0, q.c_t0, q.p_t0}, {q.a_t1, q.b_t1, q.c_t1, q.p_t1})) {
        ++culled_by_projection_only;
      }
    } else {
      const EdgeEdgeQuery q{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
      const bool hit = edge_edge_ccd(q).hit;
      hits += hit;
      if (hit) {
        ASSERT_TRUE(keeps(q)) << "EE trial " << trial;
      }
      if (!keeps(q) && may_become_coplanar({q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0},
                                           {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1})) {
        ++culled_by_projection_only;
      }
    }
  }
  EXPECT_GT(hits, trials / 50);
  EXPECT_GT(culled_by_projection_only, trials / 20);
}

TEST(ProjectionFilter, CullsAVertexCrossingThePlaneBesideTheFace) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Through the plane at (2, 2): coplanar at t = 1/2, far outside the triangle.
  EXPECT_TRUE(may_become_coplanar({a, b, c, Vec3(2, 2, 1)}, {a, b, c, Vec3(2, 2, -1)}));
  EXPECT_FALSE(
      vertex_face_may_touch_in_projection({Vec3(2, 2, 1), a, b, c}, {Vec3(2, 2, -1), a, b, c}));
  // Through the triangle, and exactly through its corner: kept.
  EXPECT_TRUE(vertex_face_may_touch_in_projection({Vec3(0.2, 0.2, 1), a, b, c},
                                                  {Vec3(0.2, 0.2, -1), a, b, c}));
  EXPECT_TRUE(
      vertex_face_may_touch_in_projection({Vec3(1, 0, 1), a, b, c}, {Vec3(1, 0, -1), a, b, c}));
  // Sliding in the plane: apart (culled) and into the triangle (kept).
  EXPECT_FALSE(
      vertex_face_may_touch_in_projection({Vec3(2, 2, 0), a, b, c}, {Vec3(3, 2, 0), a, b, c}));
  EXPECT_TRUE(
      vertex_face_may_touch_in_projection({Vec3(2, 2, 0), a, b, c}, {Vec3(0.1, 0.1, 0), a, b, c}));
}

TEST(ProjectionFilter, CullsEdgesCrossingSideBySide) {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  // Edge cd parallel to y, passing z = 0 beside ab (x = 2), and across it (x = 0.5).
  EXPECT_FALSE(edge_edge_may_touch_in_projection({a, b, Vec3(2, -1, 1), Vec3(2, 1, 1)},
                                                 {a, b, Vec3(2, -1, -1), Vec3(2, 1, -1)}));
  EXPECT_TRUE(edge_edge_may_touch_in_projection({a, b, Vec3(0.5, -1, 1), Vec3(0.5, 1, 1)},
                                                {a, b, Vec3(0.5, -1, -1), Vec3(0.5, 1, -1)}));
  // Touching at an endpoint exactly at t = 1.
  EXPECT_TRUE(edge_edge_may_touch_in_projection({a, b, Vec3(1, 0, 1), Vec3(1, 1, 1)},
                                                {a, b, Vec3(1, 0, 0), Vec3(1, 1, 0)}));
  // Coplanar for the whole step: parallel edges sliding side by side (culled), and an
  // edge sliding across ab (kept).
  EXPECT_FALSE(edge_edge_may_touch_in_projection({a, b, Vec3(2, 0.5, 0), Vec3(3, 0.5, 0)},
                                                 {a, b, Vec3(-1, 0.5, 0), Vec3(0, 0.5, 0)}));
  EXPECT_TRUE(edge_edge_may_touch_in_projection({a, b, Vec3(3, -1, 0), Vec3(3, 1, 0)},
                                                {a, b, Vec3(0.5, -1, 0), Vec3(0.5, 1, 0)}));
}

}  // namespace
}  // namespace tailor

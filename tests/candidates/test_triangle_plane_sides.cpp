// The triangle filter's corner sides: every side it certifies is the exact sign of the
// coplanarity cubic (never a wrong or an uncertain one), every build agrees, and what the
// low level drops on the strength of those sides (whole pairs of triangles, vertex-face
// pairs whose vertex stays off the plane, edge-edge pairs with an edge on one side) never
// holds a collision of the exact CCD.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/sanitized.hpp"
#include "support/triangle_pairs.hpp"
#include "tailor/candidates/triangle_plane_sides.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {
namespace {

using testing::at;
using testing::TrianglePairs;

// Triangles near one another, often crossing, touching or coplanar: on a coarse dyadic
// lattice (exact touches), random, nearly flat, near but apart (one triangle above the
// other's plane), or scaled out of the certified range.
TrianglePairs make_pairs(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> cell(-3, 3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  TrianglePairs t;
  t.faces.resize(2 * count, 3);
  t.x0.resize(6 * count, 3);
  t.x1.resize(6 * count, 3);
  for (int i = 0; i < count; ++i) {
    const bool lattice = i % 3 == 0;
    for (int v = 6 * i; v < 6 * i + 6; ++v) {
      for (Positions* x : {&t.x0, &t.x1}) {
        x->row(v) = lattice ? Vec3(cell(rng), cell(rng), cell(rng)) / 4.0
                            : Vec3(uniform(rng), uniform(rng), uniform(rng));
      }
    }
    if (i % 4 == 1) {  // the second triangle in a plane parallel to the first's, or in it
      for (int v = 6 * i; v < 6 * i + 6; ++v) {
        const double z = v < 6 * i + 3 ? 0.0 : (i % 8 == 1 ? 0.0 : 0.25);
        t.x0(v, 2) = t.x1(v, 2) = z;
      }
    }
    if (i % 5 == 2) {  // near but apart: the first flat at z <= 0, the second above it
      const double z = -0.1 * std::abs(uniform(rng));
      for (int v = 6 * i; v < 6 * i + 6; ++v) {
        for (Positions* x : {&t.x0, &t.x1}) {
          (*x)(v, 2) = v < 6 * i + 3 ? z : 1e-3 + std::abs(uniform(rng));
        }
      }
    }
    if (i % 13 == 0) {
      t.x0.middleRows(6 * i, 6) *= 0x1p210;  // beyond the certified range
      t.x1.middleRows(6 * i, 6) *= 0x1p210;
    }
    t.faces.row(2 * i) << 6 * i, 6 * i + 1, 6 * i + 2;
    t.faces.row(2 * i + 1) << 6 * i + 3, 6 * i + 4, 6 * i + 5;
    t.pairs.push_back({2 * i, 2 * i + 1});
  }
  return t;
}

// The exact sign of corner `corner` of face `points` against the plane of face `plane`.
StepSign exact_side(const TrianglePairs& t, Index plane, Index points, int corner) {
  const auto& f = t.faces;
  const Index q = f(points, corner);
  return coplanarity_sign(
      {at(t.x0, f(plane, 0)), at(t.x0, f(plane, 1)), at(t.x0, f(plane, 2)), at(t.x0, q)},
      {at(t.x1, f(plane, 0)), at(t.x1, f(plane, 1)), at(t.x1, f(plane, 2)), at(t.x1, q)});
}

TEST(TrianglePlaneSides, EveryCertifiedSideIsTheExactSignInEveryBuild) {
  const int count = testing::sanitized() ? 3000 : 30000;
  const TrianglePairs t = make_pairs(count, 5);
  std::vector<TrianglePairSides> widest(t.pairs.size()), two_lanes(t.pairs.size());
  triangle_pair_sides(t.faces, t.x0, t.x1, t.pairs, widest);
  detail::triangle_pair_sides_two_lanes(t.faces, t.x0, t.x1, t.pairs, two_lanes);
  std::int64_t certified = 0, strict = 0, out_of_range_certified = 0;
  for (std::size_t i = 0; i < t.pairs.size(); ++i) {
    const TrianglePairSides s = widest[i];
    ASSERT_EQ(s.above, two_lanes[i].above) << "pair " << i;
    ASSERT_EQ(s.below, two_lanes[i].below) << "pair " << i;
    ASSERT_EQ(s.above & s.below, 0) << "pair " << i;
    const Index first = t.pairs[i].first, second = t.pairs[i].second;
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, StepSign> sides[2] = {
          {TrianglePairSides::second_corner(k), exact_side(t, first, second, k)},
          {TrianglePairSides::first_corner(k), exact_side(t, second, first, k)}};
      for (const auto& [bit, exact] : sides) {
        const bool above = (s.above >> bit) & 1, below = (s.below >> bit) & 1;
        if (above) {
          ASSERT_EQ(exact, StepSign::positive) << "pair " << i << " bit " << bit;
        }
        if (below) {
          ASSERT_EQ(exact, StepSign::negative) << "pair " << i << " bit " << bit;
        }
        certified += above || below;
        strict += exact != StepSign::mixed;
        if (i % 13 == 0) out_of_range_certified += above || below;
      }
    }
  }
  EXPECT_EQ(out_of_range_certified, 0);
  // Nearly every strict exact sign in range is certified.
  EXPECT_GT(certified, strict * 9 / 10);
}

// The fifteen vertex-face and edge-edge pairs of two faces, each with whether the sides
// exclude it and whether the exact CCD finds a collision.
TEST(TrianglePlaneSides, WhatTheSidesExcludeNeverCollides) {
  const int count = testing::sanitized() ? 2000 : 20000;
  const TrianglePairs t = make_pairs(count, 9);
  std::vector<TrianglePairSides> sides(t.pairs.size());
  triangle_pair_sides(t.faces, t.x0, t.x1, t.pairs, sides);
  std::int64_t separated = 0, excluded = 0, collisions = 0;
  for (std::size_t i = 0; i < t.pairs.size(); ++i) {
    const TrianglePairSides s = sides[i];
    separated += s.separated();
    for (int side = 0; side < 2; ++side) {
      for (int k = 0; k < 3; ++k) {
        const bool hit = testing::vertex_face_collides(t, i, side, k);
        const int bit =
            side == 0 ? TrianglePairSides::first_corner(k) : TrianglePairSides::second_corner(k);
        const bool off = s.separated() || s.corner_off_plane(bit);
        collisions += hit;
        excluded += off;
        ASSERT_FALSE(hit && off) << "VF corner " << k << " of side " << side << ", pair " << i;
      }
    }
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        const int a1 = (a + 1) % 3, b1 = (b + 1) % 3;
        const bool hit = testing::edge_edge_collides(t, i, a, b);
        const bool off = s.separated() ||
                         s.segment_off_plane(TrianglePairSides::first_corner(a),
                                             TrianglePairSides::first_corner(a1)) ||
                         s.segment_off_plane(TrianglePairSides::second_corner(b),
                                             TrianglePairSides::second_corner(b1));
        collisions += hit;
        excluded += off;
        ASSERT_FALSE(hit && off) << "EE edges " << a << ", " << b << ", pair " << i;
      }
    }
  }
  // The test is not vacuous: pairs collide, and the sides exclude many feature pairs.
  EXPECT_GT(collisions, count / 10);
  EXPECT_GT(separated, count / 10);
  EXPECT_GT(excluded, count);
}

}  // namespace
}  // namespace tailor

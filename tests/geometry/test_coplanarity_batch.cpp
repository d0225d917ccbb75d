/// coplanarity_bernstein_batch against the scalar detail::coplanarity_bernstein_double, bit
/// for bit, on every lane width and batch size: random, coplanar, repeated-point,
/// out-of-range and non-finite queries.

#include "tailor/geometry/coplanarity_batch.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {
namespace {

using Query = std::array<Vec3, 8>;
using Terms = std::array<CoplanarityTerms, CoplanarityBatch::kCapacity>;
using Kernel = std::function<void(const CoplanarityBatch&, Terms&)>;

bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

// Queries of many kinds, so that every branch of the scalar function is compared.
std::vector<Query> make_queries() {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-20, 20);
  const auto point = [&](double scale) -> Vec3 {
    return Vec3(unit(rng), unit(rng), unit(rng)) * scale;
  };
  std::vector<Query> queries;
  for (int i = 0; i < 2000; ++i) {
    const double scale = std::ldexp(1.0, exponent(rng));
    Query q;
    for (Vec3& p : q) p = point(scale);
    switch (i % 8) {
      case 1:  // d in the plane of abc at both ends: coefficients near zero
        q[3] = q[0] + 0.3 * (q[1] - q[0]) + 0.5 * (q[2] - q[0]);
        q[7] = q[4] + 0.25 * (q[5] - q[4]) + 0.125 * (q[6] - q[4]);
        break;
      case 2:  // a repeated point: zero differences
        q[1] = q[0];
        q[5] = q[4];
        break;
      case 3:  // a tiny difference: below the guarded range
        q[2] = q[0] + Vec3(0x1p-300, 0, 0);
        break;
      case 4:  // a huge difference: above it
        q[3] = Vec3(0x1p260, 0, 0);
        break;
      case 5:  // not finite
        q[6][1] = i % 16 == 5 ? std::numeric_limits<double>::quiet_NaN()
                              : std::numeric_limits<double>::infinity();
        break;
      case 6:  // a static step: t = 1 equals t = 0
        for (int k = 0; k < 4; ++k) q[4 + k] = q[k];
        break;
      default:
        break;
    }
    queries.push_back(q);
  }
  return queries;
}

void expect_equal_to_scalar(const Kernel& kernel, const std::string& name) {
  const std::vector<Query> queries = make_queries();
  int compared = 0, in_range = 0;
  for (int count = 1; count <= CoplanarityBatch::kCapacity; ++count) {
    for (std::size_t first = 0; first + count <= queries.size(); first += count) {
      CoplanarityBatch batch;
      batch.count = count;
      for (int i = 0; i < count; ++i) {
        for (int p = 0; p < 8; ++p) batch.points[i][p] = queries[first + i][p].data();
      }
      Terms terms;
      kernel(batch, terms);
      for (int i = 0; i < count; ++i) {
        const Query& q = queries[first + i];
        double value[4], bound[4];
        const bool ok = detail::coplanarity_bernstein_double(q[0], q[1], q[2], q[3], q[4], q[5],
                                                             q[6], q[7], value, bound);
        ASSERT_EQ(terms[i].ok, ok) << name << " query " << first + i;
        ++compared;
        if (!ok) continue;
        ++in_range;
        for (int k = 0; k < 4; ++k) {
          ASSERT_TRUE(same_bits(terms[i].value[k], value[k]))
              << name << " query " << first + i << " value " << k;
          ASSERT_TRUE(same_bits(terms[i].bound[k], bound[k]))
              << name << " query " << first + i << " bound " << k;
        }
      }
    }
  }
  // Both outcomes of the guard were exercised.
  EXPECT_GT(in_range, compared / 2) << name;
  EXPECT_LT(in_range, compared) << name;
}

TEST(CoplanarityBatch, TwoLanesEqualTheScalarFilterBitForBit) {
  expect_equal_to_scalar(detail::coplanarity_bernstein_two_lanes, "two lanes");
}

TEST(CoplanarityBatch, FourLanesEqualTheScalarFilterBitForBit) {
  if (!detail::coplanarity_batch_has_four_lanes()) GTEST_SKIP() << "no AVX2 on this processor";
  expect_equal_to_scalar(detail::coplanarity_bernstein_four_lanes, "four lanes");
}

TEST(CoplanarityBatch, DispatchEqualsTheScalarFilterBitForBit) {
  expect_equal_to_scalar(coplanarity_bernstein_batch, "dispatch");
}

}  // namespace
}  // namespace tailor

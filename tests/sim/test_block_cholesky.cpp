/// @file
/// The 3 × 3-block sparse Cholesky: the same solutions as a dense Cholesky on systems with
/// the cloth step's pattern and on random block patterns (partial blocks included), a
/// refusal of indefinite matrices that leaves it usable, and clear errors on patterns it
/// cannot factorise.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <random>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sim/grid_system.hpp"
#include "tailor/sim/block_cholesky.hpp"

namespace tailor {
namespace {

using SparseMatrix = BlockCholesky::SparseMatrix;

// A random SPD matrix on `vertices` 3 × 3 blocks: random vertex pairs coupled by a
// random PSD block (some pairs through one scalar entry only, the rest of the block not
// stored), plus a diagonal. The pattern is the same for every `seed_values`.
SparseMatrix random_block_system(int vertices, unsigned seed_pattern, unsigned seed_values) {
  std::mt19937 pattern(seed_pattern), values(seed_values);
  std::uniform_int_distribution<int> vertex(0, vertices - 1), entry(0, 2);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < 3 * vertices; ++k) t.emplace_back(k, k, 4.0);
  for (int e = 0; e < 3 * vertices; ++e) {
    const int a = vertex(pattern), b = vertex(pattern);
    if (a == b) continue;
    if (e % 4 == 0) {
      // One scalar coupling c (x_{a,r} - x_{b,c})²-like: PSD, and only 2 of the 9 entries
      // of the off-diagonal blocks stored.
      const int r = entry(pattern), c = entry(pattern);
      const double k = 1 + std::abs(u(values));
      t.emplace_back(3 * a + r, 3 * a + r, k);
      t.emplace_back(3 * b + c, 3 * b + c, k);
      t.emplace_back(3 * a + r, 3 * b + c, -k);
      t.emplace_back(3 * b + c, 3 * a + r, -k);
      continue;
    }
    const Eigen::Vector3d d(u(values), u(values), u(values));
    add_vertex_coupling(t, a, b, 10 * d * d.transpose() + Eigen::Matrix3d::Identity());
  }
  SparseMatrix A(3 * vertices, 3 * vertices);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

Eigen::VectorXd dense_solution(const SparseMatrix& A, const Eigen::VectorXd& b) {
  const Eigen::LLT<Eigen::MatrixXd> llt{Eigen::MatrixXd(A)};
  EXPECT_EQ(llt.info(), Eigen::Success);
  return llt.solve(b);
}

void expect_dense_solution(BlockCholesky& cholesky, const SparseMatrix& A, const char* what) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1, 3);
  ASSERT_TRUE(cholesky.factorize(A)) << what;
  Eigen::VectorXd x;
  cholesky.solve(b, x);
  const Eigen::VectorXd reference = dense_solution(A, b);
  EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm()) << what;
  EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << what;
}

TEST(BlockCholesky, SolvesLikeADenseCholesky) {
  // The cloth step's pattern: new values on one analysis, as successive steps give them.
  std::mt19937 rng(3);
  BlockCholesky grid;
  for (int round = 0; round < 3; ++round) {
    const SparseMatrix A = grid_system(7, rng, 1.0 + round);
    if (round == 0) grid.analyze(A);
    expect_dense_solution(grid, A, "grid");
  }
  EXPECT_GT(grid.off_diagonal_blocks(), 0u);

  // Random patterns, some blocks only partly stored, a few disconnected vertices.
  for (unsigned pattern = 1; pattern <= 6; ++pattern) {
    BlockCholesky cholesky;
    for (unsigned values = 0; values < 3; ++values) {
      const SparseMatrix A = random_block_system(40, pattern, 100 * pattern + values);
      if (values == 0) cholesky.analyze(A);
      expect_dense_solution(cholesky, A, "random pattern");
    }
  }
}

TEST(BlockCholesky, TwoThreadsGiveTheOneThreadFactorBitForBit) {
  // A grid large enough for nested dissection to leave two subtrees worth a thread each.
  std::mt19937 rng(8);
  const SparseMatrix A = grid_system(48, rng, 1.0);  // 6,912 unknowns
  BlockCholesky cholesky;
  cholesky.analyze(A);
  EXPECT_GT(cholesky.parallel_rows()[0], 0u);
  EXPECT_GT(cholesky.parallel_rows()[1], 0u);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 2, -1);
  Eigen::VectorXd two, one;
  ASSERT_TRUE(cholesky.factorize(A));
  cholesky.solve(b, two);
  EXPECT_LT((A * two - b).norm(), 1e-12 * b.norm());
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    ASSERT_TRUE(cholesky.factorize(A));
    cholesky.solve(b, one);
  }
  EXPECT_EQ(one, two);
}

TEST(BlockCholesky, TakesAGivenOrder) {
  std::mt19937 rng(2);
  const SparseMatrix A = grid_system(6, rng, 1.0);
  std::vector<int> natural(36);
  for (int i = 0; i < 36; ++i) natural[static_cast<std::size_t>(i)] = i;
  BlockCholesky cholesky;
  cholesky.analyze(A, natural);
  expect_dense_solution(cholesky, A, "natural order");
  std::vector<int> twice = natural;
  twice[5] = 4;  // not a permutation
  EXPECT_THROW(cholesky.analyze(A, twice), std::invalid_argument);
  EXPECT_THROW(cholesky.analyze(A, std::vector<int>(35, 0)), std::invalid_argument);
}

TEST(BlockCholesky, RefusesIndefiniteMatricesAndStaysUsable) {
  std::mt19937 rng(5);
  // K vanishes on a uniform translation, so M + K - 40 I has the eigenvalue 1 - 40 < 0.
  const SparseMatrix indefinite = grid_system(8, rng, 1.0, -40.0);
  const SparseMatrix spd = grid_system(8, rng, 1.0);
  BlockCholesky cholesky;
  cholesky.analyze(indefinite);
  EXPECT_FALSE(cholesky.factorize(indefinite));
  // The failed factorisation leaves no state behind that spoils the next one.
  expect_dense_solution(cholesky, spd, "after a refusal");

  SparseMatrix empty(6, 6);  // no stored entry
  BlockCholesky nothing;
  nothing.analyze(empty);
  EXPECT_FALSE(nothing.factorize(empty));

  SparseMatrix not_finite = spd;
  not_finite.valuePtr()[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(cholesky.factorize(not_finite));
  expect_dense_solution(cholesky, spd, "after a NaN");
}

TEST(BlockCholesky, RejectsPatternsItCannotFactorise) {
  BlockCholesky cholesky;
  SparseMatrix four(4, 4);
  four.setIdentity();
  EXPECT_THROW(cholesky.analyze(four), std::invalid_argument);  // not 3k rows

  SparseMatrix one_sided(6, 6);
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < 6; ++k) t.emplace_back(k, k, 2.0);
  t.emplace_back(4, 1, 0.5);  // no (1, 4) entry
  one_sided.setFromTriplets(t.begin(), t.end());
  EXPECT_THROW(cholesky.analyze(one_sided), std::invalid_argument);

  SparseMatrix identity(6, 6);
  identity.setIdentity();
  EXPECT_THROW(cholesky.factorize(identity), std::invalid_argument);  // not analysed
  std::mt19937 rng(1);
  cholesky.analyze(grid_system(3, rng, 1.0));
  EXPECT_THROW(cholesky.factorize(grid_system(4, rng, 1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace tailor

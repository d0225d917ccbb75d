/// @file
/// The implicit step's linear solver: every method solves the same SPD systems, the
/// factorisations refuse matrices that are not positive definite, `automatic` reuses a
/// large factorisation only while CG with it converges.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "sim/grid_system.hpp"
#include "tailor/sim/cloth_linear_solver.hpp"

namespace tailor {
namespace {

using SparseMatrix = ClothLinearSolver::SparseMatrix;

double relative_residual(const SparseMatrix& A, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& b) {
  return (A * x - b).norm() / b.norm();
}

TEST(ClothLinearSolver, EveryMethodSolvesTheSameSystems) {
  std::mt19937 rng(11);
  ClothLinearSolver direct, supernodal, iterative;
  direct.set_method(ClothSolver::direct, 1e-12);
  supernodal.set_method(ClothSolver::supernodal, 1e-12);
  iterative.set_method(ClothSolver::iterative, 1e-12);
  // Successive systems with one pattern and new values, as the step produces them (the
  // symbolic analysis is reused from the first).
  for (int round = 0; round < 4; ++round) {
    const SparseMatrix A = grid_system(12, rng, 1.0 + round);
    Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows());
    Eigen::VectorXd xd = Eigen::VectorXd::Zero(A.rows()), xs = xd, xi = xd;
    const LinearSolveInfo d = direct.solve(A, b, xd);
    const LinearSolveInfo s = supernodal.solve(A, b, xs);
    const LinearSolveInfo i = iterative.solve(A, b, xi);
    ASSERT_TRUE(d.ok && s.ok && i.ok) << "round " << round;
    EXPECT_TRUE(d.factorized && !d.supernodal);
    EXPECT_TRUE(s.factorized && s.supernodal);
    EXPECT_FALSE(i.factorized);
    EXPECT_LT(relative_residual(A, xd, b), 1e-12);
    EXPECT_LT(relative_residual(A, xs, b), 1e-12);
    EXPECT_LT(relative_residual(A, xi, b), 1e-10);
    EXPECT_LT((xs - xd).norm(), 1e-10 * xd.norm()) << "round " << round;
  }
}

TEST(ClothLinearSolver, FactorisationsRefuseIndefiniteMatrices) {
  std::mt19937 rng(5);
  // K vanishes on a uniform translation, so M + K - 40 I has the eigenvalue 1 - 40 < 0
  // (and positive ones: K's largest eigenvalues are in the hundreds).
  const SparseMatrix A = grid_system(8, rng, 1.0, -40.0);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  for (ClothSolver method : {ClothSolver::direct, ClothSolver::supernodal}) {
    ClothLinearSolver solver;
    solver.set_method(method, 1e-12);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(A.rows());
    EXPECT_FALSE(solver.solve(A, b, x).ok) << static_cast<int>(method);
  }
}

TEST(ClothLinearSolver, AutomaticReusesOnlyFromKReuseFrom) {
  std::mt19937 rng(3);
  // The same system twice: a small one is factorised both times, a large one (from
  // kReuseFrom unknowns) is solved the second time by CG with the first factorisation.
  for (const int n : {10, 52}) {  // 300 and 8,112 unknowns
    ClothLinearSolver solver;     // automatic
    const SparseMatrix A = grid_system(n, rng, 1.0);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(A.rows());
    const LinearSolveInfo first = solver.solve(A, b, x);
    EXPECT_TRUE(first.ok && first.factorized && !first.supernodal && !first.reused);
    EXPECT_LT(relative_residual(A, x, b), 1e-12);
    x.setZero();
    const LinearSolveInfo second = solver.solve(A, b, x);
    EXPECT_TRUE(second.ok);
    EXPECT_EQ(second.reused, A.rows() >= ClothLinearSolver::kReuseFrom) << A.rows();
    EXPECT_LE(relative_residual(A, x, b), ClothLinearSolver::kReuseTolerance);
  }
}

TEST(ClothLinearSolver, AutomaticReusesALargeFactorisationWhileItPreconditionsWell) {
  std::mt19937 rng(5);
  const SparseMatrix base = grid_system(52, rng, 1.0);  // 8,112 unknowns: reused
  ASSERT_GE(base.rows(), ClothLinearSolver::kReuseFrom);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(base.rows(), -1, 2);
  ClothLinearSolver solver, exact;  // automatic, and a fresh factorisation every time
  exact.set_method(ClothSolver::supernodal, 0);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(base.rows()), reference = x;
  SparseMatrix identity(base.rows(), base.rows());
  identity.setIdentity();
  const auto solve = [&](const SparseMatrix& A) {
    const LinearSolveInfo info = solver.solve(A, b, x);
    EXPECT_TRUE(exact.solve(A, b, reference).ok);
    EXPECT_TRUE(info.ok);
    return info;
  };

  // Systems that drift slowly (as successive substeps do): the first is factorised, the
  // next kMaxReuses reuse it to kReuseTolerance within kReuseIterations, then it is renewed.
  LinearSolveInfo info = solve(base);
  EXPECT_TRUE(info.factorized && !info.supernodal && !info.reused);
  for (int k = 1; k <= ClothLinearSolver::kMaxReuses + 1; ++k) {
    const SparseMatrix A = base + (0.02 * k) * identity;
    info = solve(A);
    if (k <= ClothLinearSolver::kMaxReuses) {
      EXPECT_TRUE(info.reused && !info.factorized) << "system " << k;
      EXPECT_LE(info.iterations, ClothLinearSolver::kReuseIterations);
      EXPECT_LE(relative_residual(A, x, b), ClothLinearSolver::kReuseTolerance);
      EXPECT_LT((x - reference).norm(), 1e-4 * reference.norm());
    } else {
      EXPECT_TRUE(info.factorized && !info.reused) << "renewed after kMaxReuses";
      EXPECT_LT(relative_residual(A, x, b), 1e-12);
    }
  }

  // A system far from the kept one (another stiffness): CG misses, so it is factorised,
  // and so are the next two (back-off) although they are close to it.
  std::mt19937 other(99);
  const SparseMatrix far = grid_system(52, other, 0.01);
  info = solve(far);
  EXPECT_TRUE(info.factorized && !info.reused);
  EXPECT_LT(relative_residual(far, x, b), 1e-10);  // a hundred times worse conditioned
  for (int k = 1; k <= 3; ++k) {
    info = solve(far + (0.001 * k) * identity);
    if (k <= 2) {
      EXPECT_TRUE(info.factorized) << "back-off system " << k;
    } else {
      EXPECT_TRUE(info.reused) << "reused again after the back-off";
    }
  }
}

}  // namespace
}  // namespace tailor

#pragma once
/// @file
/// The linear solver of the implicit cloth step: one symmetric positive definite system per
/// substep, always with the same sparsity pattern.

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "tailor/sim/block_jacobi.hpp"

namespace tailor {

/// Linear solver of the implicit step.
enum class ClothSolver {
  automatic,  ///< direct up to ClothLinearSolver::kDirectSolveLimit unknowns, else iterative
  direct,     ///< sparse simplicial LDLᵀ Cholesky, Eigen, factorised every step (exact)
  iterative,  ///< conjugate gradient, block-Jacobi preconditioner, warm-started
};

/// What one solve did.
struct LinearSolveInfo {
  bool factorized = false;  ///< solved by Cholesky factorisation (false: CG)
  int iterations = 0;       ///< CG iterations (0 for the factorisation)
  bool ok = false;          ///< false if the solve failed (not SPD, not finite)
};

/// Solves A x = b for the successive systems of a cloth model (same pattern every time):
/// the symbolic analysis of the factorisation is done once.
///
/// Tried and rejected (2026-11-24): CG preconditioned by the factorisation of an earlier
/// substep's matrix. On the sleeve the arm's contact and friction blocks change too much
/// from one substep to the next: 198 of 240 solves of the elbow gesture needed more than
/// 25 iterations to reach a relative residual of 1e-10 and fell back to factorising, so
/// the solve took 5.3 ms per substep instead of 2.3.
class ClothLinearSolver {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// Systems with at most this many unknowns use a factorisation (reused or not), larger
  /// ones block-Jacobi CG.
  static constexpr Eigen::Index kDirectSolveLimit = 60000;

  /// Chooses the method and, for block-Jacobi CG, the relative residual to reach.
  void set_method(ClothSolver method, double cg_tolerance);

  /// Solves A x = b (A symmetric, both triangles stored); `x` holds a warm start for CG on
  /// entry and the solution on return.
  LinearSolveInfo solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);

 private:
  // Factorises A (the symbolic analysis once) and solves; false when A is not SPD.
  bool factorize_and_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);

  ClothSolver m_method = ClothSolver::automatic;
  double m_cg_tolerance = 1e-6;
  // Simplicial sparse LDLᵀ (Eigen, AMD ordering). Measured (elbow, one thread, ms per
  // substep) against CHOLMOD with Debian's reference BLAS: Eigen LLᵀ 2.5 vs CHOLMOD
  // supernodal 5.3 and simplicial 3.0 on the default 2,079 unknowns, 108 vs 128 and 162 on
  // the 10x sleeve's 20,790; LDLᵀ (no square roots) about 10 % below LLᵀ.
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> m_cholesky;
  bool m_analyzed = false;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, BlockJacobi> m_jacobi_cg;
};

}  // namespace tailor

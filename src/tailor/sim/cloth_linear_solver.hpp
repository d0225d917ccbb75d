#pragma once
/// @file
/// The linear solver of the implicit cloth step: one symmetric positive definite system per
/// substep, always with the same sparsity pattern.

#include <memory>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "tailor/sim/block_jacobi.hpp"

namespace tailor {

/// Linear solver of the implicit step.
enum class ClothSolver {
  automatic,   ///< direct below ClothLinearSolver::kSupernodalFrom unknowns, supernodal up
               ///< to ClothLinearSolver::kDirectSolveLimit, else iterative
  direct,      ///< sparse simplicial LDLᵀ Cholesky, Eigen, factorised every step (exact)
  supernodal,  ///< supernodal LLᵀ Cholesky, CHOLMOD, factorised every step (exact)
  iterative,   ///< conjugate gradient, block-Jacobi preconditioner, warm-started
};

/// What one solve did.
struct LinearSolveInfo {
  bool factorized = false;  ///< solved by Cholesky factorisation (false: CG)
  bool supernodal = false;  ///< the factorisation was CHOLMOD's supernodal one
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

  /// Systems with at most this many unknowns use a factorisation, larger ones
  /// block-Jacobi CG.
  static constexpr Eigen::Index kDirectSolveLimit = 60000;
  /// From this many unknowns on, `automatic` factorises with CHOLMOD's supernodal LLᵀ
  /// instead of Eigen's simplicial LDLᵀ. Measured on the sleeve's own systems (OpenBLAS
  /// with one or two threads, factorisation + solve, best of 5-50): 2,079 unknowns (default sleeve)
  /// Eigen 1.9 ms, CHOLMOD 4.3-5.4; 20,592 (10× sleeve) Eigen 121 ms, CHOLMOD 57-82.
  static constexpr Eigen::Index kSupernodalFrom = 8000;

  ClothLinearSolver();
  ~ClothLinearSolver();

  /// Chooses the method and, for block-Jacobi CG, the relative residual to reach.
  void set_method(ClothSolver method, double cg_tolerance);

  /// Solves A x = b (A symmetric, both triangles stored); `x` holds a warm start for CG on
  /// entry and the solution on return.
  LinearSolveInfo solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);

 private:
  // Factorises A (the symbolic analysis once) and solves; false when A is not SPD.
  bool factorize_and_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  // The same with CHOLMOD's supernodal LLᵀ.
  bool supernodal_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);

  ClothSolver m_method = ClothSolver::automatic;
  double m_cg_tolerance = 1e-6;
  // Simplicial sparse LDLᵀ (Eigen, AMD ordering): below kSupernodalFrom it beats
  // CHOLMOD's supernodal and simplicial factorisations (their setup per call outweighs the
  // dense kernels on small fronts); LDLᵀ (no square roots) is about 10 % below LLᵀ.
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> m_cholesky;
  bool m_analyzed = false;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, BlockJacobi> m_jacobi_cg;
  // CHOLMOD's state behind a pointer: cholmod.h stays out of the public headers.
  struct Supernodal;
  std::unique_ptr<Supernodal> m_supernodal;
};

}  // namespace tailor

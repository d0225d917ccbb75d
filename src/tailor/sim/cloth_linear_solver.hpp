#pragma once
/// @file
/// The linear solver of the implicit cloth step: one symmetric positive definite system per
/// substep, always with the same sparsity pattern.

#include <memory>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "tailor/sim/block_cholesky.hpp"
#include "tailor/sim/block_jacobi.hpp"

namespace tailor {

/// Linear solver of the implicit step.
enum class ClothSolver {
  automatic,   ///< direct up to ClothLinearSolver::kDirectSolveLimit unknowns, else
               ///< iterative; from ClothLinearSolver::kReuseFrom unknowns on, a
               ///< factorisation is reused for later systems while it preconditions
               ///< conjugate gradient well (ClothLinearSolver)
  direct,      ///< sparse Cholesky on 3 × 3 blocks (BlockCholesky), factorised every step
               ///< (exact)
  supernodal,  ///< supernodal LLᵀ Cholesky, CHOLMOD, factorised every step (exact)
  iterative,   ///< conjugate gradient, block-Jacobi preconditioner, warm-started
};

/// What one solve did.
struct LinearSolveInfo {
  bool factorized = false;  ///< solved by Cholesky factorisation (false: CG)
  bool supernodal = false;  ///< the factorisation was CHOLMOD's supernodal one
  bool reused = false;      ///< CG preconditioned by an earlier system's factorisation
  int iterations = 0;       ///< CG iterations (0 for the factorisation)
  bool ok = false;          ///< false if the solve failed (not SPD, not finite)
};

/// Solves A x = b for the successive systems of a cloth model (same pattern every time):
/// the symbolic analysis of the factorisation is done once.
///
/// `automatic` reuses a factorisation of a large system: the next systems are
/// solved by conjugate gradient preconditioned with it, to a relative residual of
/// kReuseTolerance, until CG needs more than kReuseIterations or kMaxReuses systems used
/// it; then it factorises again. The successive systems of a cloth differ by the
/// stiffness at new positions and by the arm's contact and friction blocks; with
/// CHOLMOD's factorisation the reuse made the 10× sleeve (20,592 unknowns) faster, with
/// BlockCholesky's, which is 2-3 times cheaper, it gains nothing measurable there
/// (docs/simulation.md) but is kept for larger systems. Small systems are factorised
/// every time: on the default sleeve (2,079 unknowns) a factorisation costs about 9
/// iterations, and there the arm's contacts change enough between substeps that 203 of 240 reuses
/// in the elbow gesture missed 10 iterations at any tolerance from 1e-5 to 1e-8 (an earlier
/// attempt, 2026-11-24, asked for 1e-10 within 25 iterations and missed in 198 of 240).
class ClothLinearSolver {
 public:
  /// The system matrices: column-major, int indices.
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// Systems with at most this many unknowns use a factorisation, larger ones
  /// block-Jacobi CG.
  static constexpr Eigen::Index kDirectSolveLimit = 60000;
  /// From this many unknowns on, `automatic` tries to reuse its last factorisation.
  /// BlockCholesky is also faster than CHOLMOD's supernodal LLᵀ on the sleeve's own
  /// systems (factorisation + solve, best of 5-30, 2026-11-26, a 2.45 GHz Zen 3): 2,079
  /// unknowns (default sleeve) 0.97-1.0 ms against 3.5-4.3 (Eigen's simplicial LDLᵀ 2.45);
  /// 20,592 (10× sleeve) 26-28 ms on two threads against 62-91 (Eigen 153-156).
  static constexpr Eigen::Index kReuseFrom = 8000;
  /// Relative residual at which CG with a reused factorisation stops.
  static constexpr double kReuseTolerance = 1e-6;
  /// CG iterations allowed with a reused factorisation; a system that needs more is
  /// factorised, and the next 2, 4, 8 or 16 systems (after 1, 2, 3 or more such misses in
  /// a row) are factorised without trying; one that needed more than half of them has the
  /// next one factorised.
  static constexpr int kReuseIterations = 10;
  /// Systems solved with one factorisation before it is renewed in any case.
  static constexpr int kMaxReuses = 8;

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
  // The same with CHOLMOD's supernodal LLᵀ (only on request: ClothSolver::supernodal).
  bool supernodal_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  // CG preconditioned by the kept factorisation (warm start x); false when it does not
  // reach kReuseTolerance within kReuseIterations.
  bool reuse_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   int& iterations);

  ClothSolver m_method = ClothSolver::automatic;
  double m_cg_tolerance = 1e-6;
  BlockCholesky m_cholesky;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, BlockJacobi> m_jacobi_cg;
  // CHOLMOD's state behind a pointer: cholmod.h stays out of the public headers.
  struct Supernodal;
  std::unique_ptr<Supernodal> m_supernodal;
  // The reusable factorisation (m_cholesky) of `automatic`: valid, how many systems it
  // solved since, and the CG iterations of the last of them.
  bool m_kept = false;
  int m_reuses = 0;
  int m_last_iterations = 0;
  int m_misses = 0;      // reuses in a row that did not converge
  int m_skip_reuse = 0;  // systems to factorise before trying a reuse again
};

}  // namespace tailor

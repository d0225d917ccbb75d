#include "tailor/sim/cloth_linear_solver.hpp"

namespace tailor {

void ClothLinearSolver::set_method(ClothSolver method, double cg_tolerance) {
  m_method = method;
  m_cg_tolerance = cg_tolerance;
}

bool ClothLinearSolver::factorize_and_solve(const SparseMatrix& A, const Eigen::VectorXd& b,
                                            Eigen::VectorXd& x) {
  if (!m_analyzed) {
    m_cholesky.analyzePattern(A);
    m_analyzed = true;
  }
  m_cholesky.factorize(A);
  // LDLᵀ also factorises indefinite matrices: positive pivots certify A is SPD.
  const bool spd = m_cholesky.info() == Eigen::Success && m_cholesky.vectorD().minCoeff() > 0;
  if (spd) x = m_cholesky.solve(b);
  return spd;
}

LinearSolveInfo ClothLinearSolver::solve(const SparseMatrix& A, const Eigen::VectorXd& b,
                                         Eigen::VectorXd& x) {
  LinearSolveInfo info;
  ClothSolver method = m_method;
  if (method == ClothSolver::automatic) {
    method = A.rows() <= kDirectSolveLimit ? ClothSolver::direct : ClothSolver::iterative;
  }
  switch (method) {
    case ClothSolver::iterative:
      m_jacobi_cg.setTolerance(m_cg_tolerance);
      m_jacobi_cg.setMaxIterations(1000);
      m_jacobi_cg.compute(A);
      x = m_jacobi_cg.solveWithGuess(b, x);
      info.iterations = static_cast<int>(m_jacobi_cg.iterations());
      info.ok = m_jacobi_cg.info() == Eigen::Success || m_jacobi_cg.info() == Eigen::NoConvergence;
      break;
    case ClothSolver::direct:
    case ClothSolver::automatic:
      info.factorized = true;
      info.ok = factorize_and_solve(A, b, x);
      break;
  }
  if (info.ok) info.ok = x.allFinite();
  return info;
}

}  // namespace tailor

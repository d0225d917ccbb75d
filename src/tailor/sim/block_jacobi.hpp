#pragma once
/// @file
/// A block-Jacobi preconditioner for Eigen's conjugate gradient on 3 × 3-block systems
/// (the cloth model's iterative solver).

#include <Eigen/Core>
#include <Eigen/LU>
#include <vector>

namespace tailor {

/// Block-Jacobi preconditioner for Eigen's CG: inverts the 3x3 diagonal blocks, which
/// holds a vertex's mass, its own stiffness and its contact spring exactly.
class BlockJacobi {
 public:
  /// Index type (Eigen preconditioner interface).
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };

  BlockJacobi() = default;
  /// Computes the preconditioner of `m` (see compute()).
  template <typename M>
  explicit BlockJacobi(const M& m) {
    compute(m);
  }
  /// Nothing to do: the blocks depend on the values only.
  template <typename M>
  BlockJacobi& analyzePattern(const M&) {
    return *this;
  }
  /// Same as compute().
  template <typename M>
  BlockJacobi& factorize(const M& m) {
    return compute(m);
  }
  /// Inverts each 3x3 diagonal block of `m` (3k rows); a singular block is replaced by
  /// the identity.
  template <typename M>
  BlockJacobi& compute(const M& m) {
    const Eigen::Index n = m.rows() / 3;
    m_inverse.assign(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
    for (Eigen::Index col = 0; col < m.outerSize(); ++col) {
      for (typename M::InnerIterator it(m, col); it; ++it) {
        if (it.row() / 3 == col / 3)
          m_inverse[static_cast<std::size_t>(col / 3)](it.row() % 3, col % 3) = it.value();
      }
    }
    for (Eigen::Matrix3d& block : m_inverse) {
      bool invertible = false;
      Eigen::Matrix3d inverse;
      block.computeInverseWithCheck(inverse, invertible);
      block = invertible ? inverse : Eigen::Matrix3d::Identity();
    }
    return *this;
  }
  /// Applies the preconditioner: each 3-row segment of `b` times its inverted block.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x(b.size());
    for (std::size_t i = 0; i < m_inverse.size(); ++i) {
      x.segment<3>(static_cast<Eigen::Index>(3 * i)) =
          m_inverse[i] * b.segment<3>(static_cast<Eigen::Index>(3 * i));
    }
    return x;
  }
  /// Always Eigen::Success (singular blocks fall back to the identity).
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  std::vector<Eigen::Matrix3d> m_inverse;
};

}  // namespace tailor

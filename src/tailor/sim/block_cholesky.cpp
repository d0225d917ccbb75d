#include "tailor/sim/block_cholesky.hpp"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <algorithm>
#include <stdexcept>

namespace tailor {

void BlockCholesky::analyze(const SparseMatrix& A) {
  if (A.rows() != A.cols() || A.rows() % 3 != 0 || A.rows() == 0) {
    throw std::invalid_argument("block Cholesky: the matrix must be square with 3k rows");
  }
  SparseMatrix S = A;  // compressed copy to walk
  S.makeCompressed();
  const int n = static_cast<int>(A.rows() / 3);

  // Fill-reducing ordering of the vertex graph (AMD reads both triangles).
  SparseMatrix graph(n, n);
  {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(S.nonZeros()));
    for (int j = 0; j < S.cols(); ++j) {
      for (SparseMatrix::InnerIterator it(S, j); it; ++it) {
        t.emplace_back(static_cast<int>(it.row()) / 3, j / 3, 1.0);
      }
    }
    graph.setFromTriplets(t.begin(), t.end());
  }
  if ((graph - SparseMatrix(graph.transpose())).norm() != 0) {
    throw std::invalid_argument("block Cholesky: the pattern is not symmetric");
  }
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation;
  Eigen::AMDOrdering<int>()(graph, permutation);
  m_order.assign(permutation.indices().data(), permutation.indices().data() + n);
  m_rank.assign(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < n; ++k) m_rank[static_cast<std::size_t>(m_order[k])] = k;

  // Upper blocks of the reordered matrix, column by column, and where each scalar entry
  // of A goes in them (entries of lower blocks are the same values, transposed).
  std::vector<std::vector<std::pair<int, int>>> columns(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    const int k = m_rank[static_cast<std::size_t>(j)];
    for (SparseMatrix::InnerIterator it(graph, j); it; ++it) {
      const int i = m_rank[static_cast<std::size_t>(it.row())];
      if (i <= k) columns[static_cast<std::size_t>(k)].push_back({i, 0});
    }
  }
  m_a_start.assign(static_cast<std::size_t>(n) + 1, 0);
  m_a_rows.clear();
  for (int k = 0; k < n; ++k) {
    auto& column = columns[static_cast<std::size_t>(k)];
    std::sort(column.begin(), column.end());
    for (auto& [row, slot] : column) {
      slot = static_cast<int>(m_a_rows.size());
      m_a_rows.push_back(row);
    }
    m_a_start[static_cast<std::size_t>(k) + 1] = static_cast<int>(m_a_rows.size());
  }
  m_a_values.assign(m_a_rows.size(), Block::Zero());
  m_a_target.assign(static_cast<std::size_t>(S.nonZeros()), -1);
  for (int j = 0; j < S.cols(); ++j) {
    const int k = m_rank[static_cast<std::size_t>(j / 3)];
    for (int p = S.outerIndexPtr()[j]; p < S.outerIndexPtr()[j + 1]; ++p) {
      const int r = S.innerIndexPtr()[p];
      const int i = m_rank[static_cast<std::size_t>(r / 3)];
      if (i > k) continue;
      const auto& column = columns[static_cast<std::size_t>(k)];
      const auto it = std::lower_bound(column.begin(), column.end(), std::pair<int, int>{i, -1});
      // Block (i, k) is column-major: entry (r mod 3, j mod 3).
      m_a_target[static_cast<std::size_t>(p)] = 9 * it->second + (j % 3) * 3 + r % 3;
    }
  }

  // Elimination tree and the pattern of every row of L (Liu): row k's pattern is the
  // set of nodes on the tree paths from A's upper entries of column k up to k.
  std::vector<int> parent(static_cast<std::size_t>(n), -1), mark(static_cast<std::size_t>(n), -1);
  std::vector<int> column_counts(static_cast<std::size_t>(n), 0);
  m_row_start.assign(static_cast<std::size_t>(n) + 1, 0);
  m_row_columns.clear();
  for (int k = 0; k < n; ++k) {
    mark[static_cast<std::size_t>(k)] = k;
    const auto row_begin = static_cast<std::ptrdiff_t>(m_row_columns.size());
    for (int q = m_a_start[static_cast<std::size_t>(k)]; q < m_a_start[static_cast<std::size_t>(k) + 1];
         ++q) {
      for (int i = m_a_rows[static_cast<std::size_t>(q)]; mark[static_cast<std::size_t>(i)] != k;
           i = parent[static_cast<std::size_t>(i)]) {
        if (parent[static_cast<std::size_t>(i)] == -1) parent[static_cast<std::size_t>(i)] = k;
        mark[static_cast<std::size_t>(i)] = k;
        m_row_columns.push_back(i);
        ++column_counts[static_cast<std::size_t>(i)];
      }
    }
    // A child precedes its parent in the tree, so increasing order is a topological order.
    std::sort(m_row_columns.begin() + row_begin, m_row_columns.end());
    m_row_start[static_cast<std::size_t>(k) + 1] = static_cast<int>(m_row_columns.size());
  }
  m_l_start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int i = 0; i < n; ++i) {
    m_l_start[static_cast<std::size_t>(i) + 1] =
        m_l_start[static_cast<std::size_t>(i)] + column_counts[static_cast<std::size_t>(i)];
  }
  // Column i of L receives its rows in increasing order as the rows are factorised.
  m_l_rows.assign(static_cast<std::size_t>(m_l_start.back()), 0);
  {
    std::vector<int> next(m_l_start.begin(), m_l_start.end() - 1);
    for (int k = 0; k < n; ++k) {
      for (int r = m_row_start[static_cast<std::size_t>(k)];
           r < m_row_start[static_cast<std::size_t>(k) + 1]; ++r) {
        const int i = m_row_columns[static_cast<std::size_t>(r)];
        m_l_rows[static_cast<std::size_t>(next[static_cast<std::size_t>(i)]++)] = k;
      }
    }
  }
  m_l_values.assign(m_l_rows.size(), Block::Zero());
  m_diagonal.assign(static_cast<std::size_t>(n), Block::Zero());
  m_work.assign(static_cast<std::size_t>(n), Block::Zero());
  m_work_vector.assign(static_cast<std::size_t>(n), Eigen::Vector3d::Zero());
  m_scalar_nonzeros = S.nonZeros();
  m_blocks = n;
}

bool BlockCholesky::factorize(const SparseMatrix& A) {
  if (!analyzed() || A.rows() != 3 * m_blocks || A.nonZeros() != m_scalar_nonzeros ||
      !A.isCompressed()) {
    throw std::invalid_argument("block Cholesky: factorize() needs the analysed pattern");
  }
  const double* values = A.valuePtr();
  for (Block& b : m_a_values) b.setZero();
  double* a_values = m_a_values.front().data();
  for (std::size_t p = 0; p < m_a_target.size(); ++p) {
    if (m_a_target[p] >= 0) a_values[m_a_target[p]] = values[p];
  }

  // Row k of L solves L[0:k, 0:k] · L[k, 0:k]ᵀ = A[0:k, k], in the order of its pattern;
  // then L_kk = chol(A_kk − Σ L_ki L_kiᵀ).
  for (int k = 0; k < m_blocks; ++k) {
    Block diagonal = Block::Zero();
    for (int q = m_a_start[static_cast<std::size_t>(k)]; q < m_a_start[static_cast<std::size_t>(k) + 1];
         ++q) {
      const int i = m_a_rows[static_cast<std::size_t>(q)];
      if (i == k) {
        diagonal = m_a_values[static_cast<std::size_t>(q)];
      } else {
        m_work[static_cast<std::size_t>(i)] = m_a_values[static_cast<std::size_t>(q)];
      }
    }
    for (int r = m_row_start[static_cast<std::size_t>(k)]; r < m_row_start[static_cast<std::size_t>(k) + 1];
         ++r) {
      const auto i = static_cast<std::size_t>(m_row_columns[static_cast<std::size_t>(r)]);
      // y = L_ii⁻¹ (A_ik − Σ_{j<i} L_ij y_j): the sum already subtracted into m_work[i].
      const Block y = m_diagonal[i].triangularView<Eigen::Lower>().solve(m_work[i]);
      m_work[i].setZero();
      // Column i of L holds rows below i; those already made (< k) take y's update.
      int q = m_l_start[i];
      for (; m_l_rows[static_cast<std::size_t>(q)] < k; ++q) {
        m_work[static_cast<std::size_t>(m_l_rows[static_cast<std::size_t>(q)])].noalias() -=
            m_l_values[static_cast<std::size_t>(q)] * y;
      }
      m_l_values[static_cast<std::size_t>(q)] = y.transpose();  // L_ki (row k in column i)
      diagonal.noalias() -= y.transpose() * y;
    }
    // m_work is all zero again here (every row it held was in the pattern), so a
    // refusal leaves nothing behind for the next factorisation.
    const Eigen::LLT<Block> llt(diagonal);
    if (llt.info() != Eigen::Success || !llt.matrixLLT().allFinite()) return false;
    m_diagonal[static_cast<std::size_t>(k)] = llt.matrixL();
  }
  return true;
}

void BlockCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  auto& y = m_work_vector;
  for (int k = 0; k < m_blocks; ++k) {
    y[static_cast<std::size_t>(k)] = b.segment<3>(3 * m_order[static_cast<std::size_t>(k)]);
  }
  // L y = P b, column by column.
  for (int i = 0; i < m_blocks; ++i) {
    const auto c = static_cast<std::size_t>(i);
    y[c] = m_diagonal[c].triangularView<Eigen::Lower>().solve(y[c]);
    for (int q = m_l_start[c]; q < m_l_start[c + 1]; ++q) {
      y[static_cast<std::size_t>(m_l_rows[static_cast<std::size_t>(q)])].noalias() -=
          m_l_values[static_cast<std::size_t>(q)] * y[c];
    }
  }
  // Lᵀ z = y, row by row from the last.
  for (int i = m_blocks - 1; i >= 0; --i) {
    const auto c = static_cast<std::size_t>(i);
    Eigen::Vector3d s = y[c];
    for (int q = m_l_start[c]; q < m_l_start[c + 1]; ++q) {
      s.noalias() -= m_l_values[static_cast<std::size_t>(q)].transpose() *
                     y[static_cast<std::size_t>(m_l_rows[static_cast<std::size_t>(q)])];
    }
    y[c] = m_diagonal[c].transpose().triangularView<Eigen::Upper>().solve(s);
  }
  x.resize(3 * m_blocks);
  for (int k = 0; k < m_blocks; ++k) {
    x.segment<3>(3 * m_order[static_cast<std::size_t>(k)]) = y[static_cast<std::size_t>(k)];
  }
}

}  // namespace tailor

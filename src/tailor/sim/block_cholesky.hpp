#pragma once
/// @file
/// Sparse Cholesky factorisation LLᵀ of a symmetric positive definite matrix made of 3 × 3
/// blocks (one per vertex pair), factorised block by block, on two threads.
///
/// The cloth's implicit step solves such a system every step. A scalar sparse Cholesky
/// (Eigen's SimplicialLDLT) spends most of its time on indices: each multiply-add of the
/// factorisation goes through an index lookup. Here the ordering (CHOLMOD's choice of AMD
/// or METIS nested dissection on the vertex graph), the elimination tree and the pattern
/// of L are computed per vertex, once per pattern, and each update is a dense 3 × 3
/// product (27 multiply-adds per index lookup). A row of L depends only on the rows of its
/// subtree in the elimination tree, so two disjoint parts of the tree are factorised on
/// two threads, then the path above them (docs/simulation.md gives the times).

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <vector>

namespace tailor {

/// Up-looking sparse Cholesky LLᵀ on 3 × 3 blocks, with a fill-reducing vertex ordering.
/// `analyze` once per pattern, then `factorize` and `solve` for each matrix of that pattern.
class BlockCholesky {
 public:
  /// The matrices it factorises: column-major, int indices.
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// Symbolic analysis of `A`'s pattern: A is square with 3k rows, both triangles stored,
  /// with a symmetric pattern. Throws std::invalid_argument otherwise. `order` (optional)
  /// is the elimination order of the k vertices (`order[new] = old`); by default
  /// CHOLMOD's choice of AMD or METIS, postordered.
  void analyze(const SparseMatrix& A, const std::vector<int>& order = {});
  /// True once analyze() has run.
  bool analyzed() const { return m_blocks > 0; }
  /// Numeric factorisation of `A` (the analysed pattern, symmetric values). False when A
  /// is not positive definite (a diagonal block's Cholesky fails), or not finite.
  bool factorize(const SparseMatrix& A);
  /// Solves A x = b with the last successful factorisation.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// Blocks stored in L below the diagonal (a measure of fill).
  std::size_t off_diagonal_blocks() const { return m_l_rows.size(); }
  /// Rows of L factorised on each of the two threads (0 and 0: one thread).
  std::array<std::size_t, 2> parallel_rows() const { return {m_rows[0].size(), m_rows[1].size()}; }

  /// The factorisation runs on two threads only when the estimated time (block updates of
  /// the longer part plus the path above) is below this fraction of one thread's.
  static constexpr double kSplitWorthIt = 0.8;

 private:
  using Block = Eigen::Matrix3d;

  // The stages of analyze(): the elimination order (m_order, m_rank); A's upper blocks in
  // that order and where each scalar entry goes (m_a_*); the elimination tree and the
  // pattern of every row of L (m_row_*); the rows of every column of L (m_l_start,
  // m_l_rows), returning each row's cost in block updates.
  void set_order(const SparseMatrix& graph, const std::vector<int>& order);
  void map_upper_blocks(const SparseMatrix& S, const SparseMatrix& graph);
  void row_patterns(std::vector<int>& parent, std::vector<int>& column_counts);
  std::vector<double> column_rows(const std::vector<int>& column_counts);
  // Chooses m_rows from the elimination tree and each row's cost (block updates).
  void split_for_two_threads(const std::vector<int>& parent, const std::vector<double>& cost);
  // Factorises the given rows in increasing order; false when a diagonal block is not SPD.
  bool factorize_rows(const std::vector<int>& rows);

  int m_blocks = 0;                     // block rows
  std::vector<int> m_order;             // m_order[new] = old block index
  std::vector<int> m_rank;              // m_rank[old] = new block index
  std::int64_t m_scalar_nonzeros = -1;  // A's stored entries at analysis (pattern check)
  // A's upper blocks (row ≤ column, new order) column by column: rows and values; each
  // stored scalar entry of A that lies in one is scattered to m_a_target.
  std::vector<int> m_a_start, m_a_rows;
  std::vector<Block> m_a_values;
  std::vector<int> m_a_target;  // per scalar entry of A: 9 · block + offset, or -1
  // The pattern of each row of L (strictly left of the diagonal), in increasing order.
  std::vector<int> m_row_start, m_row_columns;
  // L column by column, strictly below the diagonal: rows (increasing) and blocks; the
  // inverses of the diagonal blocks (lower triangular) apart.
  std::vector<int> m_l_start, m_l_rows;
  std::vector<Block> m_l_values;
  std::vector<Block> m_diagonal_inverse;
  std::vector<Eigen::Vector3d> m_work_vector;
  std::vector<Block> m_work;  // one block per row: the column being solved, zero between uses
  // Rows in increasing order: two parts that run at the same time, then the rest.
  std::array<std::vector<int>, 3> m_rows;
};

}  // namespace tailor

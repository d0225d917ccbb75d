#include "tailor/sim/block_cholesky.hpp"

#include <cholmod.h>
#include <tbb/parallel_invoke.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <stdexcept>

namespace tailor {
namespace {

std::size_t at(int i) {
  return static_cast<std::size_t>(i);
}

/// Fill-reducing elimination order of a symmetric graph (upper triangle of `graph`
/// stored): CHOLMOD's analysis tries AMD and nested dissection (METIS) and keeps the
/// sparser factor, postordered so that every subtree of the elimination tree is a range.
std::vector<int> fill_reducing_order(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& graph) {
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 2;
  common.method[0].ordering = CHOLMOD_AMD;
  common.method[1].ordering = CHOLMOD_METIS;
  common.postorder = 1;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  common.print = 0;
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<std::size_t>(graph.rows());
  view.nzmax = static_cast<std::size_t>(graph.nonZeros());
  view.p = const_cast<int*>(graph.outerIndexPtr());
  view.i = const_cast<int*>(graph.innerIndexPtr());
  view.x = const_cast<double*>(graph.valuePtr());
  view.stype = 1;  // upper triangle
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_PATTERN;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  cholmod_factor* factor = cholmod_analyze(&view, &common);
  if (factor == nullptr) {
    cholmod_finish(&common);
    throw std::runtime_error("block Cholesky: CHOLMOD could not order the matrix");
  }
  const int* permutation = static_cast<const int*>(factor->Perm);
  std::vector<int> order(permutation, permutation + graph.rows());
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
  return order;
}

/// The inverse of the lower triangle of `L` (the upper part of `L` is ignored): 3 × 3
/// products with it replace triangular solves, which Eigen runs through its general
/// (dynamic-size) kernel for a matrix right-hand side.
Eigen::Matrix3d lower_triangular_inverse(const Eigen::Matrix3d& L) {
  Eigen::Matrix3d inverse = Eigen::Matrix3d::Zero();
  inverse(0, 0) = 1 / L(0, 0);
  inverse(1, 1) = 1 / L(1, 1);
  inverse(2, 2) = 1 / L(2, 2);
  inverse(1, 0) = -L(1, 0) * inverse(0, 0) * inverse(1, 1);
  inverse(2, 1) = -L(2, 1) * inverse(1, 1) * inverse(2, 2);
  inverse(2, 0) = -(L(2, 0) * inverse(0, 0) + L(2, 1) * inverse(1, 0)) * inverse(2, 2);
  return inverse;
}

}  // namespace

namespace {

/// The vertex graph of A's 3 × 3 blocks, both triangles; throws when it is not symmetric.
BlockCholesky::SparseMatrix vertex_graph(const BlockCholesky::SparseMatrix& S) {
  const Eigen::Index n = S.rows() / 3;
  BlockCholesky::SparseMatrix graph(n, n);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(at(static_cast<int>(S.nonZeros())));
  for (int j = 0; j < S.cols(); ++j) {
    for (BlockCholesky::SparseMatrix::InnerIterator it(S, j); it; ++it) {
      t.emplace_back(static_cast<int>(it.row()) / 3, j / 3, 1.0);
    }
  }
  graph.setFromTriplets(t.begin(), t.end());
  if ((graph - BlockCholesky::SparseMatrix(graph.transpose())).norm() != 0) {
    throw std::invalid_argument("block Cholesky: the pattern is not symmetric");
  }
  return graph;
}

}  // namespace

void BlockCholesky::analyze(const SparseMatrix& A, const std::vector<int>& order) {
  if (A.rows() != A.cols() || A.rows() % 3 != 0 || A.rows() == 0) {
    throw std::invalid_argument("block Cholesky: the matrix must be square with 3k rows");
  }
  SparseMatrix S = A;  // compressed copy to walk
  S.makeCompressed();
  const int n = static_cast<int>(A.rows() / 3);
  const SparseMatrix graph = vertex_graph(S);
  set_order(graph, order);
  map_upper_blocks(S, graph);
  std::vector<int> parent, column_counts;
  row_patterns(parent, column_counts);
  split_for_two_threads(parent, column_rows(column_counts));

  m_l_values.assign(m_l_rows.size(), Block::Zero());
  m_diagonal_inverse.assign(at(n), Block::Zero());
  m_work.assign(at(n), Block::Zero());
  m_work_vector.assign(at(n), Eigen::Vector3d::Zero());
  m_scalar_nonzeros = S.nonZeros();
  m_blocks = n;
}

void BlockCholesky::set_order(const SparseMatrix& graph, const std::vector<int>& order) {
  const int n = static_cast<int>(graph.rows());
  m_order = order.empty() ? fill_reducing_order(graph.triangularView<Eigen::Upper>()) : order;
  m_rank.assign(at(n), -1);
  for (int k = 0; k < n; ++k) {
    const int v = k < static_cast<int>(m_order.size()) ? m_order[at(k)] : -1;
    if (m_order.size() != at(n) || v < 0 || v >= n || m_rank[at(v)] >= 0) {
      throw std::invalid_argument("block Cholesky: the order is not a permutation of the vertices");
    }
    m_rank[at(v)] = k;
  }
}

void BlockCholesky::map_upper_blocks(const SparseMatrix& S, const SparseMatrix& graph) {
  // Upper blocks of the reordered matrix, column by column, and where each scalar entry
  // of A goes in them (entries of lower blocks are the same values, transposed).
  const int n = static_cast<int>(graph.rows());
  std::vector<std::vector<std::pair<int, int>>> columns(at(n));
  for (int j = 0; j < n; ++j) {
    const int k = m_rank[at(j)];
    for (SparseMatrix::InnerIterator it(graph, j); it; ++it) {
      const int i = m_rank[at(static_cast<int>(it.row()))];
      if (i <= k) columns[at(k)].push_back({i, 0});
    }
  }
  m_a_start.assign(at(n) + 1, 0);
  m_a_rows.clear();
  for (int k = 0; k < n; ++k) {
    auto& column = columns[at(k)];
    std::sort(column.begin(), column.end());
    for (auto& [row, slot] : column) {
      slot = static_cast<int>(m_a_rows.size());
      m_a_rows.push_back(row);
    }
    m_a_start[at(k) + 1] = static_cast<int>(m_a_rows.size());
  }
  m_a_values.assign(m_a_rows.size(), Block::Zero());
  m_a_target.assign(at(static_cast<int>(S.nonZeros())), -1);
  for (int j = 0; j < S.cols(); ++j) {
    const int k = m_rank[at(j / 3)];
    for (int p = S.outerIndexPtr()[j]; p < S.outerIndexPtr()[j + 1]; ++p) {
      const int r = S.innerIndexPtr()[p];
      const int i = m_rank[at(r / 3)];
      if (i > k) continue;
      const auto& column = columns[at(k)];
      const auto it = std::lower_bound(column.begin(), column.end(), std::pair<int, int>{i, -1});
      // Block (i, k) is column-major: entry (r mod 3, j mod 3).
      m_a_target[at(p)] = 9 * it->second + (j % 3) * 3 + r % 3;
    }
  }
}

void BlockCholesky::row_patterns(std::vector<int>& parent, std::vector<int>& column_counts) {
  // Elimination tree and the pattern of every row of L (Liu): row k's pattern is the
  // set of nodes on the tree paths from A's upper entries of column k up to k.
  const int n = static_cast<int>(m_a_start.size()) - 1;
  parent.assign(at(n), -1);
  column_counts.assign(at(n), 0);
  std::vector<int> mark(at(n), -1);
  m_row_start.assign(at(n) + 1, 0);
  m_row_columns.clear();
  for (int k = 0; k < n; ++k) {
    mark[at(k)] = k;
    const auto row_begin = static_cast<std::ptrdiff_t>(m_row_columns.size());
    for (int q = m_a_start[at(k)]; q < m_a_start[at(k) + 1]; ++q) {
      for (int i = m_a_rows[at(q)]; mark[at(i)] != k; i = parent[at(i)]) {
        if (parent[at(i)] == -1) parent[at(i)] = k;
        mark[at(i)] = k;
        m_row_columns.push_back(i);
        ++column_counts[at(i)];
      }
    }
    // A child precedes its parent in the tree, so increasing order is a topological order.
    std::sort(m_row_columns.begin() + row_begin, m_row_columns.end());
    m_row_start[at(k) + 1] = static_cast<int>(m_row_columns.size());
  }
}

std::vector<double> BlockCholesky::column_rows(const std::vector<int>& column_counts) {
  const int n = static_cast<int>(column_counts.size());
  m_l_start.assign(at(n) + 1, 0);
  for (int i = 0; i < n; ++i) m_l_start[at(i) + 1] = m_l_start[at(i)] + column_counts[at(i)];
  // Column i of L receives its rows in increasing order as the rows are factorised; the
  // block updates row k costs (one per entry of column i above row k, per i in its
  // pattern) weigh it for the split into two threads.
  m_l_rows.assign(at(m_l_start.back()), 0);
  std::vector<double> cost(at(n), 1.0);
  std::vector<int> next(m_l_start.begin(), m_l_start.end() - 1);
  for (int k = 0; k < n; ++k) {
    for (int r = m_row_start[at(k)]; r < m_row_start[at(k) + 1]; ++r) {
      const int i = m_row_columns[at(r)];
      cost[at(k)] += 1 + (next[at(i)] - m_l_start[at(i)]);
      m_l_rows[at(next[at(i)]++)] = k;
    }
  }
  return cost;
}

void BlockCholesky::split_for_two_threads(const std::vector<int>& parent,
                                          const std::vector<double>& cost) {
  // Row k needs only the rows of its subtree in the elimination tree. So the subtree of
  // a node c and the rows that are neither in it nor above c can be factorised at the same
  // time, and the rows on the path above c after both. Pick the c with the shortest
  // estimated time max(subtree, rest) + path.
  const int n = static_cast<int>(parent.size());
  std::vector<double> subtree(cost), above(at(n), 0.0);
  for (int k = 0; k < n; ++k) {
    if (parent[at(k)] >= 0) subtree[at(parent[at(k)])] += subtree[at(k)];
  }
  double total = 0;
  for (int k = 0; k < n; ++k) {
    if (parent[at(k)] < 0) total += subtree[at(k)];
  }
  for (int k = n - 1; k >= 0; --k) {  // parents first
    const int p = parent[at(k)];
    if (p >= 0) above[at(k)] = above[at(p)] + cost[at(p)];
  }
  int best = -1;
  double best_time = total;
  for (int c = 0; c < n; ++c) {
    const double rest = total - subtree[at(c)] - above[at(c)];
    const double time = std::max(subtree[at(c)], rest) + above[at(c)];
    if (time < best_time) {
      best_time = time;
      best = c;
    }
  }
  for (auto& rows : m_rows) rows.clear();
  if (best < 0 || best_time > kSplitWorthIt * total) {
    for (int k = 0; k < n; ++k) m_rows[2].push_back(k);
    return;
  }
  // Membership: 0 in c's subtree, 2 on the path above c, 1 the rest.
  std::vector<char> part(at(n), 1);
  for (int a = parent[at(best)]; a >= 0; a = parent[at(a)]) part[at(a)] = 2;
  part[at(best)] = 0;
  for (int k = best - 1; k >= 0; --k) {  // descendants have smaller indices than c
    const int p = parent[at(k)];
    // p > k: its membership is final when k is visited (descending order).
    if (p >= 0 && p <= best && part[at(p)] == 0) part[at(k)] = 0;
  }
  for (int k = 0; k < n; ++k) m_rows[at(part[at(k)])].push_back(k);
}

bool BlockCholesky::factorize_rows(const std::vector<int>& rows) {
  // Row k of L solves L[0:k, 0:k] · L[k, 0:k]ᵀ = A[0:k, k], in the order of its pattern;
  // then L_kk = chol(A_kk − Σ L_ki L_kiᵀ). Everything row k reads or writes in m_work and
  // L belongs to its subtree, so rows of disjoint subtrees can run at the same time.
  for (const int k : rows) {
    Block diagonal = Block::Zero();
    for (int q = m_a_start[at(k)]; q < m_a_start[at(k) + 1]; ++q) {
      const int i = m_a_rows[at(q)];
      if (i == k) {
        diagonal = m_a_values[at(q)];
      } else {
        m_work[at(i)] = m_a_values[at(q)];
      }
    }
    for (int r = m_row_start[at(k)]; r < m_row_start[at(k) + 1]; ++r) {
      const auto i = at(m_row_columns[at(r)]);
      // y = L_ii⁻¹ (A_ik − Σ_{j<i} L_ij y_j): the sum already subtracted into m_work[i].
      const Block y = m_diagonal_inverse[i] * m_work[i];
      m_work[i].setZero();
      // Column i of L holds rows below i; those already made (< k) take y's update.
      int q = m_l_start[i];
      for (; m_l_rows[at(q)] < k; ++q) {
        m_work[at(m_l_rows[at(q)])].noalias() -= m_l_values[at(q)] * y;
      }
      m_l_values[at(q)] = y.transpose();  // L_ki (row k in column i)
      diagonal.noalias() -= y.transpose() * y;
    }
    // m_work is all zero again here (every row it held was in the pattern), so a
    // refusal leaves nothing behind for the next factorisation.
    const Eigen::LLT<Block> llt(diagonal);
    if (llt.info() != Eigen::Success || !llt.matrixLLT().allFinite()) return false;
    m_diagonal_inverse[at(k)] = lower_triangular_inverse(llt.matrixLLT());
  }
  return true;
}

bool BlockCholesky::factorize(const SparseMatrix& A) {
  if (!analyzed() || A.rows() != 3 * m_blocks || A.nonZeros() != m_scalar_nonzeros ||
      !A.isCompressed()) {
    throw std::invalid_argument("block Cholesky: factorize() needs the analysed pattern");
  }
  // No stored entry at all: not positive definite.
  if (m_a_values.empty()) return false;
  const double* values = A.valuePtr();
  for (Block& b : m_a_values) b.setZero();
  double* a_values = m_a_values.front().data();
  for (std::size_t p = 0; p < m_a_target.size(); ++p) {
    if (m_a_target[p] >= 0) a_values[m_a_target[p]] = values[p];
  }
  bool ok[2] = {true, true};
  if (!m_rows[0].empty()) {
    tbb::parallel_invoke([&] { ok[0] = factorize_rows(m_rows[0]); },
                         [&] { ok[1] = factorize_rows(m_rows[1]); });
  }
  return ok[0] && ok[1] && factorize_rows(m_rows[2]);
}

void BlockCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  auto& y = m_work_vector;
  for (int k = 0; k < m_blocks; ++k) y[at(k)] = b.segment<3>(3 * m_order[at(k)]);
  // L y = P b, column by column.
  for (int i = 0; i < m_blocks; ++i) {
    const auto c = at(i);
    y[c] = m_diagonal_inverse[c] * y[c];
    for (int q = m_l_start[c]; q < m_l_start[c + 1]; ++q) {
      y[at(m_l_rows[at(q)])].noalias() -= m_l_values[at(q)] * y[c];
    }
  }
  // Lᵀ z = y, row by row from the last.
  for (int i = m_blocks - 1; i >= 0; --i) {
    const auto c = at(i);
    Eigen::Vector3d s = y[c];
    for (int q = m_l_start[c]; q < m_l_start[c + 1]; ++q) {
      s.noalias() -= m_l_values[at(q)].transpose() * y[at(m_l_rows[at(q)])];
    }
    y[c] = m_diagonal_inverse[c].transpose() * s;
  }
  x.resize(3 * m_blocks);
  for (int k = 0; k < m_blocks; ++k) x.segment<3>(3 * m_order[at(k)]) = y[at(k)];
}

}  // namespace tailor

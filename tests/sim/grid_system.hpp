#pragma once
/// @file
/// A symmetric positive definite test system with the implicit cloth step's pattern.

#include <Eigen/SparseCore>
#include <random>
#include <vector>

namespace tailor {

// Adds the coupling k (x_a - x_b)ᵀ k (x_a - x_b) of vertices a and b (3 × 3 blocks) to `t`:
// positive semidefinite when k is.
inline void add_vertex_coupling(std::vector<Eigen::Triplet<double>>& t, int a, int b,
                                const Eigen::Matrix3d& k) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      t.emplace_back(3 * a + r, 3 * a + c, k(r, c));
      t.emplace_back(3 * b + r, 3 * b + c, k(r, c));
      t.emplace_back(3 * a + r, 3 * b + c, -k(r, c));
      t.emplace_back(3 * b + r, 3 * a + c, -k(r, c));
    }
  }
}

// A mass-spring-like system on an n × n grid of 3D points: a 3 × 3 block per vertex and
// per grid edge (the implicit step's pattern), `M + K` with K a sum of random
// positive-semidefinite edge terms and M = mass · I; `shift` is added to the diagonal.
inline Eigen::SparseMatrix<double> grid_system(int n, std::mt19937& rng, double mass,
                                               double shift = 0) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Triplet<double>> t;
  const auto id = [n](int i, int j) { return i * n + j; };
  const auto add_edge = [&](int a, int b) {
    Eigen::Vector3d d(u(rng), u(rng), u(rng));
    add_vertex_coupling(t, a, b, 50 * d * d.transpose() + 5 * Eigen::Matrix3d::Identity());
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (i + 1 < n) add_edge(id(i, j), id(i + 1, j));
      if (j + 1 < n) add_edge(id(i, j), id(i, j + 1));
      if (i + 1 < n && j + 1 < n) add_edge(id(i, j), id(i + 1, j + 1));
    }
  }
  for (int k = 0; k < 3 * n * n; ++k) t.emplace_back(k, k, mass + shift);
  Eigen::SparseMatrix<double> A(3 * n * n, 3 * n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace tailor

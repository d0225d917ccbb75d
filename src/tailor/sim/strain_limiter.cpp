/// @file
/// Edge strain limiting by Gauss-Seidel position corrections.

#include "tailor/sim/strain_limiter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>

#include "tailor/geometry/error.hpp"

namespace tailor {

std::vector<double> edge_strains(const TriangleMesh& mesh, const Positions& rest,
                                 const Positions& x) {
  const EdgeArray& edges = mesh.edges();
  std::vector<double> strains(static_cast<std::size_t>(edges.rows()));
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    const double l = (x.row(edges(e, 0)) - x.row(edges(e, 1))).norm();
    const double l0 = (rest.row(edges(e, 0)) - rest.row(edges(e, 1))).norm();
    strains[static_cast<std::size_t>(e)] = l / l0 - 1;
  }
  return strains;
}

StrainSummary strain_summary(const TriangleMesh& mesh, const Positions& rest, const Positions& x) {
  std::vector<double> strains = edge_strains(mesh, rest, x);
  StrainSummary s;
  if (strains.empty()) return s;
  s.max = *std::max_element(strains.begin(), strains.end());
  // Nearest rank: the smallest value with at least 99 % of the edges at or below it.
  const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(strains.size())));
  const auto k = std::min(strains.size() - 1, rank > 0 ? rank - 1 : 0);
  std::nth_element(strains.begin(), strains.begin() + static_cast<std::ptrdiff_t>(k),
                   strains.end());
  s.p99 = strains[k];
  return s;
}

StrainLimiter::StrainLimiter(const TriangleMesh& mesh, const Positions& rest,
                             const Eigen::VectorXd& masses, double max_strain,
                             StrainAcceleration acceleration)
    : m_max_strain(max_strain) {
  const Index nv = mesh.num_vertices();
  if (rest.rows() != nv || masses.size() != nv) {
    throw InputError(fmt::format("strain limiter: {} rest positions and {} masses for {} vertices",
                                 rest.rows(), masses.size(), nv));
  }
  if (!(max_strain >= 0) || !std::isfinite(max_strain)) {
    throw InputError(fmt::format("strain limiter: the limit must be ≥ 0, got {}", max_strain));
  }
  std::vector<double> inverse_mass(static_cast<std::size_t>(nv));
  for (Index v = 0; v < nv; ++v) {
    if (!(masses[v] > 0)) {
      throw InputError(fmt::format("strain limiter: vertex {} has mass {}", v, masses[v]));
    }
    inverse_mass[static_cast<std::size_t>(v)] = std::isinf(masses[v]) ? 0.0 : 1.0 / masses[v];
  }
  // Breadth-first distance from the pinned vertices: sweeping outwards from them carries
  // a pinned end's pull along a chain of edges in one sweep.
  std::vector<Index> level(static_cast<std::size_t>(nv), -1);
  std::deque<Index> queue;
  for (Index v = 0; v < nv; ++v) {
    if (inverse_mass[static_cast<std::size_t>(v)] == 0) {
      level[static_cast<std::size_t>(v)] = 0;
      queue.push_back(v);
    }
  }
  if (queue.empty() && nv > 0) {
    level[0] = 0;
    queue.push_back(0);
  }
  while (!queue.empty()) {
    const Index v = queue.front();
    queue.pop_front();
    for (Index e : mesh.vertex_edges(v)) {
      const Index w = mesh.edges()(e, 0) == v ? mesh.edges()(e, 1) : mesh.edges()(e, 0);
      if (level[static_cast<std::size_t>(w)] < 0) {
        level[static_cast<std::size_t>(w)] = level[static_cast<std::size_t>(v)] + 1;
        queue.push_back(w);
      }
    }
  }
  m_accelerated = acceleration == StrainAcceleration::chebyshev;
  const Index ne = mesh.num_edges();
  std::vector<Index> order(static_cast<std::size_t>(ne));
  std::iota(order.begin(), order.end(), 0);
  const auto edge_level = [&](Index e) {
    const Index a = level[static_cast<std::size_t>(mesh.edges()(e, 0))];
    const Index b = level[static_cast<std::size_t>(mesh.edges()(e, 1))];
    return std::min(a < 0 ? nv : a, b < 0 ? nv : b);
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](Index a, Index b) { return edge_level(a) < edge_level(b); });
  for (Index e : order) {
    const Index a = mesh.edges()(e, 0), b = mesh.edges()(e, 1);
    const double l0 = (rest.row(a) - rest.row(b)).norm();
    if (!(l0 > 0)) throw InputError(fmt::format("strain limiter: edge {} has zero rest length", e));
    const double wa = inverse_mass[static_cast<std::size_t>(a)];
    const double wb = inverse_mass[static_cast<std::size_t>(b)];
    if (wa + wb == 0) continue;  // both pinned: nothing can move
    m_edges.push_back({a, b});
    m_rest_length.push_back(l0);
    m_limit_squared.push_back((1 + max_strain) * l0 * (1 + max_strain) * l0);
    m_inverse_rest_squared.push_back(1 / (l0 * l0));
    m_weight0.push_back(wa / (wa + wb));
  }
}

double StrainLimiter::sweep(Positions& x, bool forward, double relaxation,
                            std::int64_t& corrections) const {
  // Squared lengths first: most edges are within the limit and need no square root.
  double worst_squared = 0;  // largest (length / rest length)²
  double* p = x.data();      // row-major: vertex v at p[3 v .. 3 v + 2]
  const std::size_t n = m_edges.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = forward ? k : n - 1 - k;
    const auto [a, b] = m_edges[i];
    double* pa = p + 3 * static_cast<std::ptrdiff_t>(a);
    double* pb = p + 3 * static_cast<std::ptrdiff_t>(b);
    const double dx = pb[0] - pa[0], dy = pb[1] - pa[1], dz = pb[2] - pa[2];
    const double l2 = dx * dx + dy * dy + dz * dz;
    worst_squared = std::max(worst_squared, l2 * m_inverse_rest_squared[i]);
    if (!(l2 > m_limit_squared[i])) continue;
    // `relaxation` > 1 removes more than the excess over the limit, but the edge never
    // becomes shorter than at rest (see apply()).
    const double l = std::sqrt(l2);
    const double excess = l - (1 + m_max_strain) * m_rest_length[i];
    const double s = std::min(relaxation * excess, l - m_rest_length[i]) / l;
    const double wa = m_weight0[i] * s, wb = (1 - m_weight0[i]) * s;
    pa[0] += wa * dx;
    pa[1] += wa * dy;
    pa[2] += wa * dz;
    pb[0] -= wb * dx;
    pb[1] -= wb * dy;
    pb[2] -= wb * dz;
    ++corrections;
  }
  return std::sqrt(worst_squared) - 1;
}

StrainLimitStats StrainLimiter::apply(Positions& x, int max_sweeps,
                                      const Constraint& constraint) const {
  StrainLimitStats stats;
  const double tolerance = 1e-9;
  // Over-relaxed sweeps while the worst strain is far above the limit: the constraint is
  // an inequality, so a length below the limit is as valid as one at it, and the
  // overshoot leaves room for the constraint that follows each sweep (plain projections
  // to the limit take hundreds of alternating sweeps where the twisted sleeve presses on
  // the arm). Near the limit, plain projections, which reach a state that neither the
  // limiter nor the constraint changes.
  double last_worst = std::numeric_limits<double>::infinity();
  // Chebyshev acceleration (see accelerated()): x_{k+1} = ω_{k+1} (x̂_{k+1} - x_{k-1})
  // + x_{k-1}, x̂_{k+1} the sweep of x_k, with ω_{k+1} = 4 / (4 - ρ² ω_k) from
  // ω = 2 / (2 - ρ²) at the first extrapolation (Wang 2015).
  Positions previous, current;
  double omega = 1;
  for (int s = 0; s < max_sweeps; ++s) {
    const std::int64_t before = stats.corrections;
    const double relaxation = last_worst > kOverRelaxedAbove * m_max_strain ? kOverRelaxation : 1.0;
    // The states two sweeps back are kept only from where extrapolation may start.
    const bool keep_states = m_accelerated && s + 1 >= kChebyshevFrom;
    if (keep_states) current = x;
    const double worst = sweep(x, s % 2 == 0, relaxation, stats.corrections);
    if (keep_states) {
      constexpr double rho2 = kChebyshevRadius * kChebyshevRadius;
      // Only after a sweep that corrected something: a state within the limit has
      // nothing to accelerate, and extrapolating would replay the constraint's last move.
      if (s >= kChebyshevFrom && stats.corrections != before) {
        omega = omega == 1 ? 2 / (2 - rho2) : 4 / (4 - rho2 * omega);
        x = omega * (x - previous) + previous;
      }
      previous = std::move(current);
    }
    last_worst = worst;
    if (s == 0) stats.max_strain_before = worst;
    ++stats.sweeps;
    const std::int64_t moved = constraint ? constraint(x) : 0;
    const bool within = stats.corrections == before || worst <= m_max_strain * (1 + tolerance);
    if (within && moved == 0) break;
  }
  double worst = 0;
  for (std::size_t i = 0; i < m_edges.size(); ++i) {
    const auto [a, b] = m_edges[i];
    worst = std::max(worst, (x.row(b) - x.row(a)).norm() / m_rest_length[i] - 1);
  }
  stats.max_strain_after = worst;
  return stats;
}

}  // namespace tailor

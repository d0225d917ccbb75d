/// @file
/// The pinned set's forms, built once.

#include "tailor/sim/pinned_vertices.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "tailor/geometry/error.hpp"

namespace tailor {

PinnedVertices::PinnedVertices(std::vector<Index> ids, const Positions& rest)
    : m_ids(std::move(ids)), m_flags(static_cast<std::size_t>(rest.rows()), 0) {
  std::sort(m_ids.begin(), m_ids.end());
  m_ids.erase(std::unique(m_ids.begin(), m_ids.end()), m_ids.end());
  m_rest.resize(static_cast<Eigen::Index>(m_ids.size()), 3);
  for (std::size_t i = 0; i < m_ids.size(); ++i) {
    const Index v = m_ids[i];
    if (v < 0 || v >= rest.rows()) {
      throw InputError(fmt::format("pinned vertex {} is not in [0, {})", v, rest.rows()));
    }
    m_flags[static_cast<std::size_t>(v)] = 1;
    m_rest.row(static_cast<Eigen::Index>(i)) = rest.row(v);
  }
}

Eigen::VectorXd PinnedVertices::with_infinite_masses(Eigen::VectorXd masses) const {
  for (Index v : m_ids) masses[v] = std::numeric_limits<double>::infinity();
  return masses;
}

}  // namespace tailor

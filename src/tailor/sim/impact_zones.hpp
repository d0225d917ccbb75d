#pragma once
/// @file
/// Rigid impact zones (Provot 1997; Harmon et al. 2008), the contact solver's fail-safe:
/// vertices of unresolved collisions are merged into zones, and each zone moves rigidly
/// from its start positions, so nothing inside a zone can collide.

#include <functional>
#include <numeric>
#include <span>
#include <vector>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Union-find over vertices, with the smallest id as the root (deterministic).
class UnionFind {
 public:
  /// `n` singleton sets, vertices 0 to n - 1.
  explicit UnionFind(Index n = 0) : m_parent(static_cast<std::size_t>(n)) {
    std::iota(m_parent.begin(), m_parent.end(), 0);
  }
  /// The root of `v`'s set.
  Index find(Index v) {
    while (m_parent[v] != v) {
      m_parent[v] = m_parent[m_parent[v]];
      v = m_parent[v];
    }
    return v;
  }
  /// Merges the sets of `a` and `b`.
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) m_parent[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<Index> m_parent;
};

/// The vertices whose end positions are prescribed (the kinematic members of a zone).
struct KinematicVertices {
  std::span<const char> pinned;       ///< per vertex: pinned (its end position is already set)
  std::span<const char> follows;      ///< per vertex: moves with the arm, to target(v)
  std::function<Vec3(Index)> target;  ///< the prescribed end position of a kinematic vertex
};

/// Moves the zone `members` rigidly from `x0` into `x1`. A zone holding kinematic members
/// (`kinematic.pinned[v]` or `kinematic.follows[v]`) moves with the rigid motion that best
/// fits their prescribed motion (Kabsch), the kinematic members themselves going exactly to
/// their targets (pinned ones are left alone). A zone without any moves with its members'
/// mass-weighted mean linear and angular displacement (`inverse_mass` per vertex).
void move_zone_rigidly(std::span<const Index> members, const Positions& x0,
                       const Eigen::VectorXd& inverse_mass, const KinematicVertices& kinematic,
                       Positions& x1);

}  // namespace tailor

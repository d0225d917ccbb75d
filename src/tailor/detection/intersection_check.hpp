#pragma once
/// @file
/// Independent static check that a cloth state is intersection-free (docs/design.md §4): every
/// pair of cloth triangles and every cloth-obstacle triangle pair, with the exact
/// triangle-triangle test, accelerated by a BVH over the triangles' boxes.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// What check_intersections found. Pair lists hold the first `max_pairs` pairs in
/// increasing order (deterministic); the counts are complete.
struct IntersectionReport {
  std::int64_t self_candidate_pairs = 0;      ///< cloth face pairs whose boxes overlap
  std::int64_t obstacle_candidate_pairs = 0;  ///< cloth-obstacle face pairs whose boxes overlap
  /// Cloth face pairs sharing no vertex that intersect.
  std::int64_t self_intersections = 0;
  /// Cloth face pairs sharing a vertex or an edge that meet beyond the shared feature.
  std::int64_t adjacent_intersections = 0;
  /// Cloth-obstacle face pairs that intersect (touching counts).
  std::int64_t obstacle_intersections = 0;
  /// Cloth faces with zero area (collinear corners).
  std::int64_t degenerate_faces = 0;
  /// Adjacent cloth pairs with a degenerate face, which the adjacent test cannot decide.
  std::int64_t undecided_adjacent_pairs = 0;
  /// First intersecting cloth face pairs `(f, g)`, `f < g` (adjacent ones included).
  std::vector<std::pair<Index, Index>> self_pairs;
  /// First intersecting `(cloth face, obstacle face)` pairs.
  std::vector<std::pair<Index, Index>> obstacle_pairs;

  /// All intersections counted (self, adjacent and obstacle).
  std::int64_t total() const {
    return self_intersections + adjacent_intersections + obstacle_intersections;
  }
  /// True when nothing intersects.
  bool intersection_free() const { return total() == 0; }
};

/// Checks cloth positions `x` (one row per cloth vertex) for self-intersections and, when
/// `obstacle` and `y` are given, for intersections with the obstacle. Exact on the input
/// doubles. Cloth faces incident to a vertex of `obstacle_exempt_vertices` (e.g. vertices
/// pinned onto the obstacle's surface) are not tested against the obstacle. Throws
/// InputError if a row count does not match its mesh or an exempt id is out of range.
IntersectionReport check_intersections(const TriangleMesh& cloth, const Positions& x,
                                       const TriangleMesh* obstacle = nullptr,
                                       const Positions* y = nullptr, std::size_t max_pairs = 10,
                                       std::span<const Index> obstacle_exempt_vertices = {});

}  // namespace tailor

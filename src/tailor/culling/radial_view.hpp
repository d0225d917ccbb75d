#pragma once
/// @file
/// Radial-view culling around observation points (Wong et al. 2013; the paper §2.2).

#include <cstdint>
#include <vector>

#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Counts of one radial-view classification.
struct RadialViewCounts {
  std::int64_t clusters_certified = 0;
  std::int64_t triangles_positive = 0;      ///< real and ghost, observer strictly in front
  std::int64_t triangles_negative = 0;      ///< observer strictly behind
  std::int64_t triangles_undetermined = 0;  ///< sign changes or cannot be certified
};

/// Observation points and clusters of a tube-like garment.
///
/// Each observer sits at the centroid of one section loop (a ring of cloth vertices) and
/// moves with it. Each vertex belongs to the observer nearest to it on the build frame
/// (the bisector rule of the paper for two observers), each triangle to the lowest
/// cluster among its vertices.
/// A cluster is closed by ghost triangles (a fan from each open boundary loop to the
/// loop's centroid). It is certified collision-free for a step only when it is one
/// edge-connected, edge-manifold, consistently oriented patch and every real and ghost
/// triangle sees its observer strictly on one and the same side over the whole step:
/// then the radial projection of the closed surface onto a sphere around the observer
/// is a covering of degree one, hence injective, so no two non-incident features meet.
class RadialViewClusters {
 public:
  RadialViewClusters() = default;
  /// `section_loops`: one vertex-id loop per observer (at least one vertex each). Throws
  /// InputError for an empty loop or an out-of-range vertex id.
  RadialViewClusters(const TriangleMesh& mesh, const Positions& x_build,
                     std::vector<std::vector<Index>> section_loops);

  Index num_clusters() const { return static_cast<Index>(m_cluster_faces.size()); }
  /// Faces of cluster `c`, ascending.
  const std::vector<Index>& faces(Index c) const { return m_cluster_faces[c]; }
  /// Whether cluster `c` can ever be certified (its topology allows the theorem).
  bool certifiable(Index c) const { return m_certifiable[c] != 0; }
  /// Observer position of cluster `c` for the given frame.
  Vec3 observer(Index c, const Positions& x) const;

  /// For each cluster, whether it is certified over the step from `x0` to `x1`.
  std::vector<char> certify(const Positions& x0, const Positions& x1,
                            RadialViewCounts& counts) const;

 private:
  const TriangleMesh* m_mesh = nullptr;
  std::vector<std::vector<Index>> m_section_loops;
  std::vector<std::vector<Index>> m_cluster_faces;
  std::vector<char> m_certifiable;
  /// Open boundary loops of each cluster, directed so that the ghost triangle
  /// (loop[i+1], loop[i], centre) matches the orientation of the cluster's faces.
  std::vector<std::vector<std::vector<Index>>> m_ghost_loops;
};

}  // namespace tailor

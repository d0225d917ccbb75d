#pragma once
/// @file
/// Radial-view clusters of a tube-like garment (Wong et al. 2013; the paper §2.2): the
/// observers, the overlapping clusters they watch, and the ghost triangles closing them.

#include <cstdint>
#include <vector>

#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Observers and clusters of radial-view culling, built once per topology.
///
/// Each observer sits at the centroid of one section loop (a ring of cloth vertices) and
/// moves with it; with loops taken along the arm, the observers follow the skeleton.
/// Each vertex is watched by its kWatchers = 3 nearest observers (distances on the build
/// frame), and a face belongs to every cluster that watches its three vertices. With
/// more than three observers along a tube the clusters follow the skeleton: the cluster
/// of observer i spans from about observer i-2 to i+2, clusters overlap, and a fold at a
/// joint only spoils the triangles near it in each cluster that holds it. With three
/// observers or fewer every cluster is the whole mesh, seen from each observer.
///
/// Measured on the sleeve (recorded substeps of the three gestures, Tang's candidate
/// pairs left after radial view): five observers 0.1 m apart with three watchers 0.27 /
/// 0.11 / 0.17 (elbow / raise / twist), with two watchers 0.42 / 0.21 / 0.29; three
/// observers (upper arm, elbow, forearm), each cluster the whole sleeve, 0.12 / 0.08 /
/// 0.10 at the same cost. Pairs are mostly cut by the edge planes of
/// radial_view_culling.hpp, and each more viewpoint on a pair is one more chance.
///
/// A cluster is usable only when its faces form one edge-connected, edge-manifold,
/// consistently oriented patch whose boundary is a set of simple vertex loops: each loop
/// is then closed by ghost triangles (a fan to the loop's centroid), and the cluster with
/// its ghosts is a closed surface (see radial_view_culling.hpp for what that allows).
class RadialViewClusters {
 public:
  /// At most this many observers (cluster membership is a 64-bit mask per face).
  static constexpr int kMaxObservers = 64;
  /// How many nearest observers watch each vertex.
  static constexpr int kWatchers = 3;

  RadialViewClusters() = default;
  /// `section_loops`: one vertex-id loop per observer (at least one vertex each). Throws
  /// InputError for no loop, an empty loop, an out-of-range vertex id or more than
  /// kMaxObservers loops.
  RadialViewClusters(const TriangleMesh& mesh, const Positions& x_build,
                     std::vector<std::vector<Index>> section_loops);

  /// The mesh the clusters were built on.
  const TriangleMesh& mesh() const { return *m_mesh; }
  /// Number of clusters: one per observer (section loop).
  Index num_clusters() const { return static_cast<Index>(m_cluster_faces.size()); }
  /// Faces of cluster `c`, ascending.
  const std::vector<Index>& faces(Index c) const { return m_cluster_faces[c]; }
  /// Bit c is set when face `f` belongs to cluster c.
  std::uint64_t member_mask(Index f) const { return m_member_mask[f]; }
  /// Whether cluster `c` is a patch that ghost triangles close (see the class comment).
  bool usable(Index c) const { return m_usable[c] != 0; }
  /// Open boundary loops of cluster `c`, each directed so that the ghost triangle
  /// (loop[i+1], loop[i], centroid) matches the orientation of the cluster's faces.
  const std::vector<std::vector<Index>>& ghost_loops(Index c) const { return m_ghost_loops[c]; }
  /// Observer of cluster `c` in frame `x`: the centroid of its section loop.
  Vec3 observer(Index c, const Positions& x) const;

 private:
  const TriangleMesh* m_mesh = nullptr;
  std::vector<std::vector<Index>> m_section_loops;
  std::vector<std::vector<Index>> m_cluster_faces;
  std::vector<std::uint64_t> m_member_mask;
  std::vector<char> m_usable;
  std::vector<std::vector<std::vector<Index>>> m_ghost_loops;
};

/// Centroid of the vertices `vertices` in frame `x`.
Vec3 loop_centroid(const Positions& x, const std::vector<Index>& vertices);

}  // namespace tailor

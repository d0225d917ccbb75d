#pragma once
/// @file
/// Radial-view culling of candidate triangle pairs (Wong et al. 2013, "Radial view based
/// culling for continuous self-collision detection of skeletal models"; the paper §2.2),
/// with the per-triangle classification that lets it cut inside clusters that bend and
/// fold, not only inside clusters that stay convex-looking as a whole.
///
/// ## What is classified
/// For each usable cluster (radial_view.hpp) and each step, every real and ghost triangle
/// is classified against the cluster's observer o(t) by the exact Bernstein sign of
/// det(b-a, c-a, o-a) over the step (geometry/coplanarity_sign.hpp): *positive* when the
/// observer stays strictly on the side of the triangle it should see (behind an outward
/// face), *negative* when it stays strictly on the other side, *undetermined* otherwise.
/// Ghost vertices (loop centroids) and observers move linearly between their positions at
/// t = 0 and t = 1 as computed in double: that is their definition, used by every test.
///
/// ## The theorem (degree argument)
/// Let S(t) be the cluster closed by its ghost fans and π_t(x) = (x - o(t)) / |x - o(t)|.
/// (1) While o(t) is on no triangle of S(t), π_t has a constant integer degree w, the
///     winding number of S(t) around o(t). A positive or negative triangle never holds o
///     (its sign never vanishes); an undetermined one must have a swept box disjoint from
///     the observer's, else the cluster is not used for the step. w is computed exactly at
///     t = 0 (culling/winding_number.hpp); the cluster is used only when |w| = 1, the
///     orientation being chosen so that w = 1 (a cluster oriented inward swaps positive
///     and negative).
/// (2) Let B(t) be the negative and undetermined triangles (real and ghost) and U(t) the
///     directions not in π_t(B(t)). On the positive triangles π_t preserves orientation
///     and is a local homeomorphism away from vertices; a regular direction in U(t) only
///     meets positive triangles, each meeting counting +1 toward w = 1, so it has exactly
///     one preimage; a vertex whose star wraps k ≥ 2 times around its direction would give
///     nearby regular directions k preimages. So every direction in U(t) is seen once.
/// (3) Two non-incident features (VF or EE) that touch at time t at point q are two
///     different points of S(t) seen in the same direction, so that direction lies in
///     π_t(B(t)): both triangles holding the features have a point seen, at time t, in a
///     direction in which a negative or undetermined triangle is seen.
/// (4) The view cone of a triangle over the step holds every direction in which it is
///     seen at any t (culling/view_cone.hpp). A positive real triangle whose view cone is
///     disjoint from the view cone of every negative and undetermined triangle (real or
///     ghost) of the cluster is *clean*: no point of it touches any non-incident feature of
///     the cluster during the step. Every VF/EE pair a CTP (f, g) stands for has one
///     feature on f and the other on g, so a pair of faces of one cluster in which one face
///     is clean stands for no collision and is culled.
/// (5) Independently of the classification (it needs no closed surface, only a moving
///     point): let (a, b) be an edge of face f and c its third vertex. If c stays strictly
///     on one side of the plane through o(t), a(t), b(t) and the three vertices of face g
///     stay strictly on the other side over the whole step (exact Bernstein signs), that
///     plane separates f(t) from g(t) at every t: g is seen entirely beyond the edge (a, b)
///     of f, their radial projections are disjoint, and the pair is culled. (A degenerate
///     plane, o on the line ab, makes every sign vanish: no cull.)
/// When every triangle of a cluster is positive, every face is clean: the whole cluster is
/// certified, the original radial-view test of Wong et al. and of the paper.
///
/// Pairs of faces that share no usable cluster are left to the BVH traversal; culling
/// only removes pairs from what the traversal (with normal cones where it applies)
/// produced, so radial view never costs more candidate pairs than the traversal alone.

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "tailor/culling/radial_view.hpp"
#include "tailor/culling/triangle_pair.hpp"
#include "tailor/culling/view_cone.hpp"

namespace tailor {

/// Counts of one step's radial-view classification (real and ghost triangles, summed over
/// the clusters; a face in two clusters counts twice).
struct RadialViewCounts {
  std::int64_t clusters_classified = 0;     ///< usable clusters classified
  std::int64_t clusters_used = 0;           ///< clusters whose winding number was ±1
  std::int64_t clusters_certified = 0;      ///< clusters with every triangle positive
  std::int64_t triangles_positive = 0;      ///< observer strictly on the seeing side
  std::int64_t triangles_negative = 0;      ///< observer strictly on the other side
  std::int64_t triangles_undetermined = 0;  ///< the sign may vanish, or cluster not used
  std::int64_t faces_clean = 0;             ///< positive faces seen where no other is
  std::int64_t pairs_culled = 0;            ///< candidate triangle pairs removed
};

/// The side from which the observer of a cluster sees one of its faces over the step, once
/// the cluster is classified.
enum class FaceSign : signed char {
  negative = -1,      ///< its back, throughout the step
  undetermined = 0,   ///< the face's plane may pass the observer (or the cluster is unusable)
  positive = 1,       ///< its front, throughout the step
  positive_clean = 2  ///< its front, and no triangle of the cluster can block the view of it
};

/// The per-step state of radial-view culling over a fixed set of clusters.
///
/// One protocol per step: begin_step(); then, for each candidate pair, edge_planes_separate()
/// (rule (5), computing the few raw signs it reads), which remembers the clusters in which
/// a pair it kept could still be culled by (4) (with clean faces off: only clusters in
/// which both faces of a kept pair have the same nonzero raw sign, since a certified cluster
/// has every face positive); then classify_wanted() classifies those clusters only, and
/// classified_clean() (or pair_culled()) finishes the pairs. classify() is the same
/// protocol with every cluster wanted: begin_step() then classify_wanted(true), after which
/// pair_culled() answers for any pair. Both cull exactly the same pairs: a pair is culled
/// iff rule (5) holds in a shared cluster or one of its faces is clean in a shared
/// cluster, and the wanted clusters include every cluster that can make a kept pair's face
/// clean. A sleeve's contact-free clusters, where every pair is culled by (5), are then
/// never classified (their O(faces) classification is most of the cost).
class RadialViewCulling {
 public:
  RadialViewCulling() = default;
  /// Builds the clusters (see RadialViewClusters for the arguments and errors).
  RadialViewCulling(const TriangleMesh& mesh, const Positions& x_build,
                    std::vector<std::vector<Index>> section_loops);

  /// The clusters the classification works on.
  const RadialViewClusters& clusters() const { return m_clusters; }

  /// begin_step(x0, x1, find_clean), then classify_wanted(true): classifies every cluster
  /// over the step from `x0` to `x1` (parallel over clusters).
  /// `x0` and `x1` must stay alive while pair_culled() and cull() use this step.
  /// `find_clean`: also find the clean faces (view cones of every face and blocking
  /// triangle). They only matter for pairs of faces that share a vertex: a clean face and
  /// a face it does not touch are seen in disjoint regions, and then the edge planes of
  /// (5) separate them too (two disjoint convex spherical polygons are separated by a
  /// great circle through an edge of one of them; measured on the elbow gesture with the
  /// isolated set: the same candidate pairs with or without clean faces). So callers
  /// whose candidates never share a vertex (adjacency culling on) may skip it.
  RadialViewCounts classify(const Positions& x0, const Positions& x1, bool find_clean = true);

  /// Starts a step of the lazy way (class comment) from `x0` to `x1` (kept alive by the
  /// caller for the step), classifying nothing yet; `find_clean` as for classify().
  void begin_step(const Positions& x0, const Positions& x1, bool find_clean);
  /// Rule (5) of the header for faces f and g in some cluster they share, over the step
  /// begun. When it answers false, remembers the shared clusters whose classification
  /// could still cull the pair. Safe to call from several threads at once.
  bool edge_planes_separate(Index f, Index g);
  /// Classifies the clusters remembered by edge_planes_separate() since begin_step(), or
  /// every usable cluster when `every_cluster` (for the counts of all of them; the pairs
  /// culled are the same) (parallel over clusters); the counts cover the clusters
  /// classified.
  RadialViewCounts classify_wanted(bool every_cluster = false);
  /// Whether f or g is clean in a cluster they share (after classify() or
  /// classify_wanted()).
  bool classified_clean(Index f, Index g) const {
    return !m_clean_mask.empty() &&
           ((m_clean_mask[f] | m_clean_mask[g]) & shared_clusters(f, g)) != 0;
  }

  /// Whether the pair of faces (f, g) cannot collide over the classified step.
  bool pair_culled(Index f, Index g) const;

  /// Removes from `pairs` every pair culled over the classified step (order kept);
  /// returns how many were removed.
  std::int64_t cull(std::vector<TrianglePair>& pairs) const;

  /// Bit c set when face `f` is clean in cluster c over the classified step.
  std::uint64_t clean_mask(Index f) const { return m_clean_mask.empty() ? 0 : m_clean_mask[f]; }
  /// Per face of cluster `c` (in clusters().faces(c) order), over the classified step (all
  /// undetermined when the cluster's winding number is not ±1; empty when the cluster is
  /// not usable or was not classified this step).
  const std::vector<FaceSign>& face_signs(Index c) const { return m_state[c].face_sign; }

 private:
  // Raw signs are StepSign values (-1, 0, 1) of coplanarity_sign(a, b, c, observer), kept
  // as signed char for std::atomic_ref; this one marks a sign not computed yet this step.
  static constexpr signed char kNotComputed = 2;
  struct ClusterState {
    Vec3 observer0 = Vec3::Zero(), observer1 = Vec3::Zero();
    // coplanarity_sign(a, b, c, observer) per face, computed when first needed (atomic
    // access while pairs are tested in parallel); empty when the cluster is not usable.
    std::vector<signed char> face_raw;
    std::vector<FaceSign> face_sign;  // as face_signs()
    RadialViewCounts counts;
    // Scratch reused from step to step.
    std::vector<Vec3> unit0, unit1;  // directions to the cluster's vertices
    std::vector<char> unit_ok;
    std::vector<ViewCone> cones;
  };
  // The usable clusters holding both f and g.
  std::uint64_t shared_clusters(Index f, Index g) const {
    return m_clusters.member_mask(f) & m_clusters.member_mask(g) & m_usable;
  }
  // The raw sign of face `f` in cluster `c` (a usable cluster holding f) over the step.
  signed char raw_sign(Index c, Index f) const;
  // Rule (5) in any of `clusters`; when it fails and `wanted` is given, adds the clusters
  // whose classification could still cull the pair.
  bool separated_in(Index f, Index g, std::uint64_t clusters, std::uint64_t* wanted) const;
  RadialViewCounts classify_clusters(std::uint64_t clusters);
  void build_local_faces(Index c);
  void classify_cluster(Index c);
  void find_clean_faces(Index c, const std::vector<std::size_t>& blocking,
                        const std::vector<ViewCone>& ghost_cones);

  RadialViewClusters m_clusters;
  // mutable: raw signs are a per-step cache filled by const queries.
  mutable std::vector<ClusterState> m_state;
  // Per face (empty until some face is clean: most steps of a sleeve never need it).
  std::vector<std::uint64_t> m_clean_mask;
  bool m_clean_mask_dirty = false;  // some bit set since it was last cleared
  std::uint64_t m_usable = 0;       // bit c: cluster c is usable
  bool m_find_clean = true;
  // Clusters to classify (lazy way); updated through std::atomic_ref (keeps the class
  // movable).
  alignas(std::atomic_ref<std::uint64_t>::required_alignment) std::uint64_t m_wanted = 0;
  // Per cluster: its vertices, and each face's three vertices as indices into them (built
  // when clean faces are first wanted in the cluster).
  std::vector<std::vector<Index>> m_cluster_vertices;
  std::vector<std::vector<std::array<Index, 3>>> m_local_faces;
  // Position of face f within clusters().faces(c), per cluster; -1 if not a member.
  std::vector<std::vector<Index>> m_slot;
  const Positions* m_x0 = nullptr;  // the step
  const Positions* m_x1 = nullptr;
};

}  // namespace tailor

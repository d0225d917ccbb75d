#include "tailor/culling/bvh_traversal.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "tailor/culling/contour_test.hpp"

namespace tailor {
namespace {

// Node pairs under this many faces in total are traversed by one task.
constexpr Index kTaskGrain = 512;

// Subtrees of at most this many faces (and, for a self-test, fewer than a group: below a
// group no node keeps a normal cone) are compared leaf by leaf, lanes() leaves at a time
// (StepBoundColumns). A leaf pair passes the same test as in the walk, and every node
// above it holds its bounds (a node's bounds are the union of its children's), so the walk
// would have reached it: the candidates are the walk's.
Index bucket_faces() {
  return StepBoundColumns::lanes();
}

}  // namespace

// One traversal: the recursion carries the output of the task it runs in, so the
// thread-local lookup happens once per task, not once per node pair.
class CandidateTraversal::Walk {
 public:
  Walk(const TriangleMesh& mesh, const TraversalOptions& options,
       tbb::enumerable_thread_specific<ThreadOutput>& outputs)
      : m_mesh(mesh), m_options(options), m_outputs(outputs) {}

  // What the normal cone of an inner node says about its self-test.
  enum class ConeVerdict {
    open,       // test below it
    skipped,    // the cone alone skips it (the contour test is off: not a certificate)
    certified,  // cone and contour: nothing below it can collide
  };
  ConeVerdict cone_verdict(const MeshBvh& bvh, const NodeContours& contours, StepPositions step,
                           Index node, ThreadOutput& out) {
    if (!m_options.normal_cones) return ConeVerdict::open;
    const std::optional<Vec3> axis = bvh.acute_axis(node);
    if (!axis) return ConeVerdict::open;
    if (!m_options.contour_test) {
      ++out.counts.nodes_culled_by_cones;
      return ConeVerdict::skipped;
    }
    ++out.counts.contour_tests;
    if (contours.has_single_loop(node) &&
        contour_stays_simple(contours.loop(node), step.x0, step.x1, *axis)) {
      ++out.counts.nodes_culled_by_cones;
      return ConeVerdict::certified;
    }
    ++out.counts.contour_tests_failed;
    return ConeVerdict::open;
  }

  // Returns true when the node was certified by its cone and the contour test.
  bool self(const MeshBvh& bvh, const NodeContours& contours, StepPositions step, Index node,
            ThreadOutput& out) {
    if (bvh.is_leaf(node)) return false;
    const ConeVerdict verdict = cone_verdict(bvh, contours, step, node, out);
    if (verdict != ConeVerdict::open) return verdict == ConeVerdict::certified;
    if (bvh.size(node) < MeshBvh::kGroupFaces) {
      bucket_self(bvh, node, out);
      return false;
    }
    const Index left = bvh.left(node), right = bvh.right(node);
    if (bvh.size(node) > kTaskGrain) {
      tbb::parallel_invoke([&] { self(bvh, contours, step, left, m_outputs.local()); },
                           [&] { self(bvh, contours, step, right, m_outputs.local()); },
                           [&] { pair(bvh, left, bvh, right, m_outputs.local()); });
    } else {
      self(bvh, contours, step, left, out);
      self(bvh, contours, step, right, out);
      pair(bvh, left, bvh, right, out);
    }
    return false;
  }

  // Tests the boxes of a node pair (counted as visited) and, when its faces may meet during
  // the step (MeshBvh::may_meet: boxes at both ends, bvh/step_boxes.hpp), walks it.
  void pair(const MeshBvh& a, Index node_a, const MeshBvh& b, Index node_b, ThreadOutput& out) {
    ++out.counts.node_pairs_visited;
    if (a.may_meet(node_a, b, node_b)) overlapping_pair(a, node_a, b, node_b, out);
  }

  // The two child pairs of an inner node pair: the larger node is split (the inner one
  // when the other is a leaf).
  struct ChildPairs {
    Index first_a, first_b, second_a, second_b;
  };
  [[gnu::always_inline]] static ChildPairs child_pairs(const MeshBvh& a, Index node_a,
                                                       const MeshBvh& b, Index node_b) {
    const bool leaf_a = a.is_leaf(node_a), leaf_b = b.is_leaf(node_b);
    if (leaf_b || (!leaf_a && a.size(node_a) >= b.size(node_b))) {
      return {a.left(node_a), node_b, a.right(node_a), node_b};
    }
    return {node_a, b.left(node_b), node_a, b.right(node_b)};
  }

  // Two leaves that may meet: a candidate triangle pair unless adjacency culls it.
  [[gnu::always_inline]] void leaf_pair(const MeshBvh& a, Index node_a, const MeshBvh& b,
                                        Index node_b, ThreadOutput& out) {
    Index f = a.leaf_face(node_a), g = b.leaf_face(node_b);
    if (m_options.adjacency_culling && share_vertex(f, g)) return;
    if (f > g) std::swap(f, g);
    out.push({f, g});
  }

  // A node pair that may meet: a candidate triangle pair at two leaves, otherwise both
  // child pairs are tested here, so that the many pairs that cannot meet cost no call.
  // Below the task grain the walk goes on in small_pair.
  void overlapping_pair(const MeshBvh& a, Index node_a, const MeshBvh& b, Index node_b,
                        ThreadOutput& out) {
    if (a.is_leaf(node_a) && b.is_leaf(node_b)) return leaf_pair(a, node_a, b, node_b, out);
    if (a.size(node_a) <= bucket_faces() && b.size(node_b) <= bucket_faces()) {
      return bucket_pair(a, node_a, b, node_b, out);
    }
    const ChildPairs c = child_pairs(a, node_a, b, node_b);
    out.counts.node_pairs_visited += 2;
    const bool overlap1 = a.may_meet(c.first_a, b, c.first_b);
    const bool overlap2 = a.may_meet(c.second_a, b, c.second_b);
    if (a.size(node_a) + b.size(node_b) <= kTaskGrain) {
      if (overlap1) small_pair(a, c.first_a, b, c.first_b, out);
      if (overlap2) small_pair(a, c.second_a, b, c.second_b, out);
    } else if (overlap1 && overlap2) {
      tbb::parallel_invoke(
          [&] { overlapping_pair(a, c.first_a, b, c.first_b, m_outputs.local()); },
          [&] { overlapping_pair(a, c.second_a, b, c.second_b, m_outputs.local()); });
    } else if (overlap1) {
      overlapping_pair(a, c.first_a, b, c.first_b, out);
    } else if (overlap2) {
      overlapping_pair(a, c.second_a, b, c.second_b, out);
    }
  }

  // overlapping_pair below the task grain: the same walk with no task to spawn, so the
  // recursion is a small function.
  void small_pair(const MeshBvh& a, Index node_a, const MeshBvh& b, Index node_b,
                  ThreadOutput& out) {
    if (a.is_leaf(node_a) && b.is_leaf(node_b)) return leaf_pair(a, node_a, b, node_b, out);
    if (a.size(node_a) <= bucket_faces() && b.size(node_b) <= bucket_faces()) {
      return bucket_pair(a, node_a, b, node_b, out);
    }
    const ChildPairs c = child_pairs(a, node_a, b, node_b);
    out.counts.node_pairs_visited += 2;
    if (a.may_meet(c.first_a, b, c.first_b)) small_pair(a, c.first_a, b, c.first_b, out);
    if (a.may_meet(c.second_a, b, c.second_b)) {
      small_pair(a, c.second_a, b, c.second_b, out);
    }
  }

  // The leaves of a node pair that may meet, compared leaf by leaf (bucket_faces()).
  void bucket_pair(const MeshBvh& a, Index node_a, const MeshBvh& b, Index node_b,
                   ThreadOutput& out) {
    ++out.counts.leaf_buckets;
    const Index first_a = a.first_leaf(node_a), first_b = b.first_leaf(node_b);
    const int count_a = static_cast<int>(a.size(node_a));
    std::uint32_t masks[StepBoundColumns::kLanes];
    b.leaf_bounds().may_meet_masks(a.leaf_bounds(), {first_a, count_a},
                                   {first_b, static_cast<int>(b.size(node_b))},
                                   std::min(a.bound_directions(), b.bound_directions()), masks);
    for (int r = 0; r < count_a; ++r) {
      for (std::uint32_t mask = masks[r]; mask != 0; mask &= mask - 1) {
        bucket_leaf_pair(a, first_a + r, b, first_b + std::countr_zero(mask), out);
      }
    }
  }
  // The leaf pairs inside a node, compared leaf by leaf.
  void bucket_self(const MeshBvh& bvh, Index node, ThreadOutput& out) {
    ++out.counts.leaf_buckets;
    const Index first = bvh.first_leaf(node);
    const int count = static_cast<int>(bvh.size(node));
    std::uint32_t masks[MeshBvh::kGroupFaces];
    bvh.leaf_bounds().may_meet_masks_within({first, count}, bvh.bound_directions(), masks);
    for (int r = 0; r < count; ++r) {
      for (std::uint32_t mask = masks[r]; mask != 0; mask &= mask - 1) {
        bucket_leaf_pair(bvh, first + r, bvh, first + std::countr_zero(mask), out);
      }
    }
  }
  // leaf_pair() for leaves given in leaf order.
  void bucket_leaf_pair(const MeshBvh& a, Index leaf_a, const MeshBvh& b, Index leaf_b,
                        ThreadOutput& out) {
    if (m_options.adjacency_culling &&
        corners_share_vertex(a.corners_at_leaf(leaf_a), b.corners_at_leaf(leaf_b))) {
      return;
    }
    Index f = a.face_at_leaf(leaf_a), g = b.face_at_leaf(leaf_b);
    if (f > g) std::swap(f, g);
    out.push({f, g});
  }

 private:
  static bool corners_share_vertex(const std::array<Index, 3>& a, const std::array<Index, 3>& b) {
    const Index a0 = a[0], a1 = a[1], a2 = a[2];
    bool shared = false;
    for (const Index v : b) shared |= (v == a0) | (v == a1) | (v == a2);
    return shared;
  }
  // Faces f and g share a vertex (TriangleMesh::faces_share_vertex, inlined: it runs for
  // every leaf pair that may meet).
  bool share_vertex(Index f, Index g) const {
    const FaceArray& faces = m_mesh.faces();
    const Index a0 = faces(f, 0), a1 = faces(f, 1), a2 = faces(f, 2);
    bool shared = false;
    for (int k = 0; k < 3; ++k) {
      const Index v = faces(g, k);
      shared |= (v == a0) | (v == a1) | (v == a2);
    }
    return shared;
  }

  const TriangleMesh& m_mesh;
  const TraversalOptions& m_options;
  tbb::enumerable_thread_specific<ThreadOutput>& m_outputs;
};

TraversalCounts& TraversalCounts::operator+=(const TraversalCounts& other) {
  node_pairs_visited += other.node_pairs_visited;
  leaf_buckets += other.leaf_buckets;
  nodes_culled_by_cones += other.nodes_culled_by_cones;
  contour_tests += other.contour_tests;
  contour_tests_failed += other.contour_tests_failed;
  return *this;
}

void CandidateTraversal::clear() {
  for (ThreadOutput& out : m_outputs) {
    for (std::size_t b = 0; b < out.used; ++b) out.blocks[b].clear();
    out.used = 0;
    out.counts = {};
  }
}

bool CandidateTraversal::self(const MeshBvh& bvh, const NodeContours& contours, StepPositions step,
                              const TraversalOptions& options) {
  if (bvh.empty()) return false;
  if (!bvh.boxes_current()) {
    throw std::logic_error("CandidateTraversal::self: the BVH's boxes are not refitted");
  }
  return Walk(*m_mesh, options, m_outputs).self(bvh, contours, step, 0, m_outputs.local());
}

bool CandidateTraversal::certify_root(const MeshBvh& bvh, const NodeContours& contours,
                                      StepPositions step, const TraversalOptions& options) {
  if (bvh.empty() || bvh.is_leaf(0)) return false;
  return Walk(*m_mesh, options, m_outputs)
             .cone_verdict(bvh, contours, step, 0, m_outputs.local()) ==
         Walk::ConeVerdict::certified;
}

std::vector<std::span<const TrianglePair>> CandidateTraversal::blocks() const {
  std::vector<std::span<const TrianglePair>> result;
  for (const ThreadOutput& out : m_outputs) {
    for (std::size_t b = 0; b < out.used; ++b) result.emplace_back(out.blocks[b]);
  }
  return result;
}

std::int64_t CandidateTraversal::size() const {
  std::int64_t total = 0;
  for (const ThreadOutput& out : m_outputs) {
    for (std::size_t b = 0; b < out.used; ++b)
      total += static_cast<std::int64_t>(out.blocks[b].size());
  }
  return total;
}

TraversalCounts CandidateTraversal::counts() const {
  TraversalCounts total;
  for (const ThreadOutput& out : m_outputs) total += out.counts;
  return total;
}

}  // namespace tailor

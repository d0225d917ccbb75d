#include "tailor/bvh/bvh_layout.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_invoke.h>

namespace tailor {
namespace {

// How a split divided its range.
struct Split {
  Index left;                  // the first `left` primitives of the range form the left child
  bool left_is_patch = false;  // ...one patch in breadth-first order from their first face
};

// Builds a pre-order layout top-down over order[first, first + count) with `splitter`
// (Split split(range, node, is_patch, scratch) const, reordering the range): the left
// subtree (2·left - 1 nodes) follows its parent, the right subtree follows it. Subtrees
// of at least `parallel_from` primitives split their children in parallel (the ranges are
// disjoint and each split depends only on its range, so the tree does not depend on
// scheduling); smaller ones run with an explicit stack (deep trees stay off the call
// stack).
template <class Splitter>
class LayoutBuilder {
 public:
  LayoutBuilder(const Splitter& splitter, std::vector<Index>& order, BvhLayout& layout,
                Index parallel_from)
      : m_splitter(splitter), m_order(order), m_layout(layout), m_parallel_from(parallel_from) {}

  void build(Index node, Index first, Index count, bool is_patch = false) {
    if (count < m_parallel_from) return build_sequential(node, first, count, is_patch);
    const Split split = split_node(node, first, count, is_patch, m_scratch.local());
    tbb::parallel_invoke(
        [&] { build(node + 1, first, split.left, split.left_is_patch); },
        [&] { build(node + 2 * split.left, first + split.left, count - split.left); });
  }

 private:
  using Scratch = typename Splitter::Scratch;

  // Records node's count and right child (or primitive); returns the split.
  Split split_node(Index node, Index first, Index count, bool is_patch, Scratch& scratch) {
    m_layout.count[node] = count;
    if (count == 1) {
      m_layout.right[node] = m_order[first];
      return {0};
    }
    const std::span<Index> range(m_order.data() + first, static_cast<std::size_t>(count));
    const Split split = m_splitter.split(range, node, is_patch, scratch);
    m_layout.right[node] = node + 2 * split.left;
    return split;
  }

  void build_sequential(Index node, Index first, Index count, bool is_patch) {
    struct Task {
      Index node, first, count;
      bool is_patch;
    };
    Scratch& scratch = m_scratch.local();
    std::vector<Task> stack{{node, first, count, is_patch}};
    while (!stack.empty()) {
      const Task task = stack.back();
      stack.pop_back();
      const Split split = split_node(task.node, task.first, task.count, task.is_patch, scratch);
      if (task.count == 1) continue;
      const Index left = split.left;
      stack.push_back({task.node + 2 * left, task.first + left, task.count - left, false});
      stack.push_back({task.node + 1, task.first, left, split.left_is_patch});
    }
  }

  const Splitter& m_splitter;
  std::vector<Index>& m_order;
  BvhLayout& m_layout;
  const Index m_parallel_from;
  tbb::enumerable_thread_specific<Scratch> m_scratch;
};

// The layout of n primitives (0..n-1, in that order at the root) by `splitter`.
template <class Splitter>
BvhLayout build_layout(Index n, const Splitter& splitter, Index parallel_from) {
  BvhLayout layout;
  if (n == 0) return layout;
  layout.right.assign(static_cast<std::size_t>(2 * n - 1), -1);
  layout.count.assign(static_cast<std::size_t>(2 * n - 1), 0);
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  LayoutBuilder<Splitter>(splitter, order, layout, parallel_from).build(0, 0, n);
  return layout;
}

// Halves a range at the median of its centres along their widest axis.
struct MedianSplitter {
  struct Scratch {};

  std::span<const Vec3> centers;

  Split split(std::span<Index> range, Index /*node*/, bool /*is_patch*/, Scratch&) const {
    Eigen::Array3d low = centers[range[0]].array(), high = low;
    for (Index p : range) {
      low = low.min(centers[p].array());
      high = high.max(centers[p].array());
    }
    int axis = 0;
    (high - low).maxCoeff(&axis);
    const Index half = static_cast<Index>(range.size()) / 2;
    std::nth_element(range.begin(), range.begin() + half, range.end(), [&](Index a, Index b) {
      return centers[a][axis] < centers[b][axis] || (centers[a][axis] == centers[b][axis] && a < b);
    });
    return {half};
  }
};

}  // namespace

BvhLayout build_median_split_layout(std::span<const Vec3> centers) {
  return build_layout(static_cast<Index>(centers.size()), MedianSplitter{centers}, 8192);
}

namespace {

// Edge-adjacency of a face subset (faces sharing an edge), in CSR form over local ids.
struct FaceGraph {
  std::vector<Index> offsets, neighbors;

  FaceGraph(const TriangleMesh& mesh, std::span<const Index> faces) {
    std::vector<Index> local(static_cast<std::size_t>(mesh.num_faces()), -1);
    for (std::size_t i = 0; i < faces.size(); ++i) local[faces[i]] = static_cast<Index>(i);
    offsets.assign(faces.size() + 1, 0);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      for (Index e : mesh.face_edges(faces[i])) {
        for (Index g : mesh.edge_faces(e)) {
          if (g != faces[i] && local[g] >= 0) neighbors.push_back(local[g]);
        }
      }
      offsets[i + 1] = static_cast<Index>(neighbors.size());
    }
  }
  std::span<const Index> of(Index i) const {
    return {neighbors.data() + offsets[i], static_cast<std::size_t>(offsets[i + 1] - offsets[i])};
  }
};

// Per-thread work space of a split: the breadth-first queue and where each component
// starts in it.
struct SplitScratch {
  std::vector<Index> queue, component_starts;
};

// Splits face ranges. Ranges being split at the same time are disjoint, so they touch
// disjoint entries of the shared stamp and mark arrays: subtrees split in parallel. A
// split depends only on its range's faces and their order (the task id only has to be
// unique), so the tree does not depend on scheduling.
class SurfaceSplitter {
 public:
  SurfaceSplitter(const FaceGraph& graph, std::span<const Vec3> centers)
      : m_graph(graph), m_centers(centers), m_state(centers.size(), -1) {}

  using Scratch = SplitScratch;

  // Reorders `range` into its two children. `task` is unique among all splits (the node
  // id). `is_patch`: the range is one patch listed in breadth-first order from its first
  // face (the left child of a one-patch split).
  Split split(std::span<Index> range, Index task, bool is_patch, SplitScratch& scratch) const {
    const Index half = static_cast<Index>(range.size()) / 2;
    // A prefix of a breadth-first order is the breadth-first order of its own patch from
    // the same face (every face's breadth-first parent comes before it). So the left child
    // of a one-patch split is one patch swept from a peripheral face of its parent, which
    // lies at its own periphery too: it is halved along the same sweep, with no new search
    // (the trees are at least as tight: cloth-ball's, the folded and pleated cloths' and
    // the sleeve's steps visit no more node pairs, docs/log.md).
    if (is_patch) return {half, true};
    // A face's state in this split: 3 task (in the range), + 1 (reached by the first
    // pass), + 2 (by the second). One array, one access per neighbour.
    const Index in_range = 3 * task, first_pass = in_range + 1, second_pass = in_range + 2;
    for (Index f : range) std::atomic_ref<Index>(m_state[f]).store(in_range, kRelaxed);
    if (!find_components(range, in_range, first_pass, scratch)) {
      return {split_components(range, half, scratch), false};
    }
    // One patch: breadth-first from a peripheral face (the last one the first pass
    // reached); the first half goes left.
    const Index far = scratch.queue[range.size() - 1];
    const Index tail = visit_from(far, first_pass, second_pass, scratch.queue.data(), 0);
    std::copy(scratch.queue.begin(), scratch.queue.begin() + tail, range.begin());
    return {half, true};
  }

 private:
  static constexpr std::memory_order kRelaxed = std::memory_order_relaxed;

  // Lists the range's components breadth-first, in range order, into the scratch queue
  // (moving its faces from `in_range` to `reached`); true when there is only one.
  bool find_components(std::span<const Index> range, Index in_range, Index reached,
                       SplitScratch& scratch) const {
    scratch.queue.resize(range.size());
    scratch.component_starts.clear();
    Index tail = 0;
    for (Index f : range) {
      if (m_state[f] != in_range) continue;
      scratch.component_starts.push_back(tail);
      tail = visit_from(f, in_range, reached, scratch.queue.data(), tail);
    }
    scratch.component_starts.push_back(tail);
    return scratch.component_starts.size() == 2;
  }

  // Writes to queue[tail...] every face in state `from` reachable from `start` through
  // such faces, moving them to state `to`; returns the new tail. A neighbour outside the
  // range may be written by another thread at this moment (never with this split's
  // states), hence the atomic accesses.
  Index visit_from(Index start, Index from, Index to, Index* queue, Index tail) const {
    const Index* offsets = m_graph.offsets.data();
    const Index* neighbors = m_graph.neighbors.data();
    Index* state = m_state.data();
    Index head = tail;
    queue[tail++] = start;
    std::atomic_ref<Index>(state[start]).store(to, kRelaxed);
    while (head < tail) {
      const Index f = queue[head++];
      for (Index i = offsets[f]; i < offsets[f + 1]; ++i) {
        const Index g = neighbors[i];
        std::atomic_ref<Index> g_state(state[g]);
        if (g_state.load(kRelaxed) == from) {
          g_state.store(to, kRelaxed);
          queue[tail++] = g;
        }
      }
    }
    return tail;
  }

  // Whole components to each side, ordered by their centres along the widest axis, as
  // close to half of the faces on the left as whole components allow (at least one each).
  Index split_components(std::span<Index> range, Index half, const SplitScratch& scratch) const {
    const std::vector<Index>& starts = scratch.component_starts;
    const std::size_t count = starts.size() - 1;
    std::vector<Vec3> mean(count, Vec3::Zero());
    Eigen::Array3d low = Eigen::Array3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Array3d high = -low;
    for (std::size_t c = 0; c < count; ++c) {
      for (Index i = starts[c]; i < starts[c + 1]; ++i) mean[c] += m_centers[scratch.queue[i]];
      mean[c] /= starts[c + 1] - starts[c];
      low = low.min(mean[c].array());
      high = high.max(mean[c].array());
    }
    int axis = 0;
    (high - low).maxCoeff(&axis);
    std::vector<Index> order(count);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
      return mean[a][axis] < mean[b][axis] || (mean[a][axis] == mean[b][axis] && a < b);
    });
    Index written = 0, left = 0;
    for (std::size_t k = 0; k < count; ++k) {
      const Index c = order[k];
      for (Index i = starts[c]; i < starts[c + 1]; ++i) range[written++] = scratch.queue[i];
      // Close the left side once it holds half, leaving the right side non-empty.
      if (left == 0 && (written >= half || k + 2 == count)) left = written;
    }
    return left;
  }

  const FaceGraph& m_graph;
  std::span<const Vec3> m_centers;
  mutable std::vector<Index> m_state;
};

}  // namespace

BvhLayout build_surface_layout(const TriangleMesh& mesh, std::span<const Index> faces,
                               std::span<const Vec3> centers) {
  if (faces.empty()) return {};
  const FaceGraph graph(mesh, faces);
  return build_layout(static_cast<Index>(faces.size()), SurfaceSplitter(graph, centers), 2048);
}

}  // namespace tailor

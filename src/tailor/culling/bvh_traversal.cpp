#include "tailor/culling/bvh_traversal.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_invoke.h>

#include "tailor/culling/contour_test.hpp"

namespace tailor {
namespace {

// Node pairs under this many primitives in total are traversed by one task.
constexpr Index kTaskGrain = 512;

struct ThreadOutput {
  std::vector<TrianglePair> pairs;
  TraversalCounts counts;
};

class Traversal {
 public:
  Traversal(const TriangleMesh& mesh, const TraversalOptions& options)
      : m_mesh(mesh), m_options(options) {}

  void self(const MeshBvh& bvh, const NodeContours& contours, StepPositions step, Index node) {
    const Bvh& tree = bvh.tree();
    if (tree.is_leaf(node)) return;
    ThreadOutput& out = m_outputs.local();
    if (m_options.normal_cones && bvh.cone(node).is_under_90_degrees()) {
      if (!m_options.contour_test) {
        ++out.counts.nodes_culled_by_cones;
        return;
      }
      ++out.counts.contour_tests;
      if (contours.has_single_loop(node) &&
          contour_stays_simple(contours.loop(node), step.x0, step.x1, bvh.cone(node).axis)) {
        ++out.counts.nodes_culled_by_cones;
        return;
      }
      ++out.counts.contour_tests_failed;
    }
    const Index left = tree.left(node), right = tree.right(node);
    if (static_cast<Index>(tree.primitives_under(node).size()) > kTaskGrain) {
      tbb::parallel_invoke([&] { self(bvh, contours, step, left); },
                           [&] { self(bvh, contours, step, right); },
                           [&] { pair(bvh, left, bvh, right); });
    } else {
      self(bvh, contours, step, left);
      self(bvh, contours, step, right);
      pair(bvh, left, bvh, right);
    }
  }

  void pair(const MeshBvh& a, Index node_a, const MeshBvh& b, Index node_b) {
    const Bvh& ta = a.tree();
    const Bvh& tb = b.tree();
    ThreadOutput& out = m_outputs.local();
    ++out.counts.node_pairs_visited;
    if (!ta.box(node_a).overlaps(tb.box(node_b))) return;
    const bool leaf_a = ta.is_leaf(node_a), leaf_b = tb.is_leaf(node_b);
    if (leaf_a && leaf_b) {
      Index f = a.face(ta.primitive(node_a)), g = b.face(tb.primitive(node_b));
      if (m_options.adjacency_culling && m_mesh.faces_share_vertex(f, g)) return;
      if (f > g) std::swap(f, g);
      out.pairs.push_back({f, g});
      return;
    }
    const auto size_a = static_cast<Index>(ta.primitives_under(node_a).size());
    const auto size_b = static_cast<Index>(tb.primitives_under(node_b).size());
    const bool split_a = leaf_b || (!leaf_a && size_a >= size_b);
    const Index child1_a = split_a ? ta.left(node_a) : node_a;
    const Index child2_a = split_a ? ta.right(node_a) : node_a;
    const Index child1_b = split_a ? node_b : tb.left(node_b);
    const Index child2_b = split_a ? node_b : tb.right(node_b);
    if (size_a + size_b > kTaskGrain) {
      tbb::parallel_invoke([&] { pair(a, child1_a, b, child1_b); },
                           [&] { pair(a, child2_a, b, child2_b); });
    } else {
      pair(a, child1_a, b, child1_b);
      pair(a, child2_a, b, child2_b);
    }
  }

  void collect(std::vector<TrianglePair>& pairs, TraversalCounts& counts) {
    for (ThreadOutput& out : m_outputs) {
      pairs.insert(pairs.end(), out.pairs.begin(), out.pairs.end());
      counts += out.counts;
    }
  }

 private:
  const TriangleMesh& m_mesh;
  const TraversalOptions& m_options;
  tbb::enumerable_thread_specific<ThreadOutput> m_outputs;
};

}  // namespace

TraversalCounts& TraversalCounts::operator+=(const TraversalCounts& other) {
  node_pairs_visited += other.node_pairs_visited;
  nodes_culled_by_cones += other.nodes_culled_by_cones;
  contour_tests += other.contour_tests;
  contour_tests_failed += other.contour_tests_failed;
  return *this;
}

void self_traversal(const TriangleMesh& mesh, const MeshBvh& bvh, const NodeContours& contours,
                    StepPositions step, const TraversalOptions& options,
                    std::vector<TrianglePair>& pairs, TraversalCounts& counts) {
  if (bvh.tree().empty()) return;
  Traversal traversal(mesh, options);
  traversal.self(bvh, contours, step, 0);
  traversal.collect(pairs, counts);
}

void pair_traversal(const TriangleMesh& mesh, const MeshBvh& a, const MeshBvh& b,
                    const TraversalOptions& options, std::vector<TrianglePair>& pairs,
                    TraversalCounts& counts) {
  if (a.tree().empty() || b.tree().empty()) return;
  Traversal traversal(mesh, options);
  traversal.pair(a, 0, b, 0);
  traversal.collect(pairs, counts);
}

}  // namespace tailor

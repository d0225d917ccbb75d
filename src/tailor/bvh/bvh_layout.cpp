#include "tailor/bvh/bvh_layout.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace tailor {

BvhLayout build_median_split_layout(std::span<const Vec3> centers) {
  BvhLayout layout;
  const Index n = static_cast<Index>(centers.size());
  if (n == 0) return layout;
  layout.right.assign(static_cast<std::size_t>(2 * n - 1), -1);
  layout.count.assign(static_cast<std::size_t>(2 * n - 1), 0);
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);

  // Pre-order numbering with an explicit stack (deep trees stay off the call stack): the
  // left subtree (2·half - 1 nodes) follows its parent, the right subtree follows it.
  struct Task {
    Index node, first, count;
  };
  std::vector<Task> stack{{0, 0, n}};
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    layout.count[task.node] = task.count;
    const auto begin = order.begin() + task.first;
    if (task.count == 1) {
      layout.right[task.node] = *begin;
      continue;
    }
    Eigen::Array3d low = centers[*begin].array(), high = low;
    for (Index i = 1; i < task.count; ++i) {
      low = low.min(centers[begin[i]].array());
      high = high.max(centers[begin[i]].array());
    }
    int axis = 0;
    (high - low).maxCoeff(&axis);
    const Index half = task.count / 2;
    std::nth_element(begin, begin + half, begin + task.count, [&](Index a, Index b) {
      return centers[a][axis] < centers[b][axis] || (centers[a][axis] == centers[b][axis] && a < b);
    });
    layout.right[task.node] = task.node + 2 * half;
    stack.push_back({task.node + 2 * half, task.first + half, task.count - half});
    stack.push_back({task.node + 1, task.first, half});
  }
  return layout;
}

}  // namespace tailor

namespace tailor {
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

class SurfaceSplitter {
 public:
  SurfaceSplitter(const FaceGraph& graph, std::span<const Vec3> centers)
      : m_graph(graph),
        m_centers(centers),
        m_stamp(centers.size(), -1),
        m_mark(centers.size(), -1) {}

  // Reorders `range` so that its first `returned` faces form the left child.
  Index split(std::span<Index> range, Index task) {
    for (Index f : range) m_stamp[f] = task;
    // Components of the range (breadth-first, in range order).
    m_queue.clear();
    m_component_starts.clear();
    for (Index f : range) {
      if (m_mark[f] == task) continue;
      m_component_starts.push_back(static_cast<Index>(m_queue.size()));
      visit_from(f, task);
    }
    m_component_starts.push_back(static_cast<Index>(m_queue.size()));
    const Index half = static_cast<Index>(range.size()) / 2;
    if (m_component_starts.size() > 2) return split_components(range, half);
    // One patch: breadth-first from a peripheral face; the first half goes left.
    const Index far = m_queue.back();
    m_queue.clear();
    visit_from(far, ~task);  // a fresh mark value for this pass
    std::copy(m_queue.begin(), m_queue.end(), range.begin());
    return half;
  }

 private:
  // Appends to m_queue every face of the current range reachable from `start`, marking
  // them with `mark`.
  void visit_from(Index start, Index mark) {
    std::size_t head = m_queue.size();
    m_queue.push_back(start);
    m_mark[start] = mark;
    const Index task = mark >= 0 ? mark : ~mark;
    while (head < m_queue.size()) {
      const Index f = m_queue[head++];
      for (Index g : m_graph.of(f)) {
        if (m_stamp[g] == task && m_mark[g] != mark) {
          m_mark[g] = mark;
          m_queue.push_back(g);
        }
      }
    }
  }

  // Whole components to each side, ordered by their centres along the widest axis, as
  // close to half of the faces on the left as whole components allow (at least one each).
  Index split_components(std::span<Index> range, Index half) {
    const std::size_t count = m_component_starts.size() - 1;
    std::vector<Vec3> mean(count, Vec3::Zero());
    Eigen::Array3d low = Eigen::Array3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Array3d high = -low;
    for (std::size_t c = 0; c < count; ++c) {
      for (Index i = m_component_starts[c]; i < m_component_starts[c + 1]; ++i) {
        mean[c] += m_centers[m_queue[i]];
      }
      mean[c] /= m_component_starts[c + 1] - m_component_starts[c];
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
      for (Index i = m_component_starts[c]; i < m_component_starts[c + 1]; ++i) {
        range[written++] = m_queue[i];
      }
      // Close the left side once it holds half, leaving the right side non-empty.
      if (left == 0 && (written >= half || k + 2 == count)) left = written;
    }
    return left;
  }

  const FaceGraph& m_graph;
  std::span<const Vec3> m_centers;
  std::vector<Index> m_stamp, m_mark, m_queue, m_component_starts;
};

}  // namespace

BvhLayout build_surface_layout(const TriangleMesh& mesh, std::span<const Index> faces,
                               std::span<const Vec3> centers) {
  BvhLayout layout;
  const Index n = static_cast<Index>(faces.size());
  if (n == 0) return layout;
  layout.right.assign(static_cast<std::size_t>(2 * n - 1), -1);
  layout.count.assign(static_cast<std::size_t>(2 * n - 1), 0);
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  const FaceGraph graph(mesh, faces);
  SurfaceSplitter splitter(graph, centers);

  struct Task {
    Index node, first, count;
  };
  std::vector<Task> stack{{0, 0, n}};
  Index tasks = 0;
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    layout.count[task.node] = task.count;
    if (task.count == 1) {
      layout.right[task.node] = order[task.first];
      continue;
    }
    const std::span<Index> range(order.data() + task.first, static_cast<std::size_t>(task.count));
    const Index left = splitter.split(range, tasks++);
    const Index right_node = task.node + 2 * left;
    layout.right[task.node] = right_node;
    stack.push_back({right_node, task.first + left, task.count - left});
    stack.push_back({task.node + 1, task.first, left});
  }
  return layout;
}

}  // namespace tailor

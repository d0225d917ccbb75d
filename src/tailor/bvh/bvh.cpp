#include "tailor/bvh/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace tailor {
Bvh::Bvh(std::span<const Aabb> primitive_boxes) {
  const Index n = static_cast<Index>(primitive_boxes.size());
  if (n == 0) return;
  const Index num_nodes = 2 * n - 1;
  m_left.assign(num_nodes, -1);
  m_right.assign(num_nodes, -1);
  m_parent.assign(num_nodes, -1);
  m_first.assign(num_nodes, 0);
  m_count.assign(num_nodes, 0);
  m_boxes.resize(num_nodes);
  m_leaf_of_primitive.assign(n, -1);
  m_primitive_order.resize(n);
  std::iota(m_primitive_order.begin(), m_primitive_order.end(), 0);

  std::vector<Vec3> centers(n);
  for (Index p = 0; p < n; ++p) centers[p] = primitive_boxes[p].center();

  // Top-down median split in pre-order; an explicit stack keeps deep trees off the call stack.
  struct Task {
    Index node, first, count, parent;
  };
  std::vector<Task> stack{{0, 0, n, -1}};
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    m_first[task.node] = task.first;
    m_count[task.node] = task.count;
    m_parent[task.node] = task.parent;
    const auto begin = m_primitive_order.begin() + task.first;
    if (task.count == 1) {
      m_right[task.node] = *begin;
      m_leaf_of_primitive[*begin] = task.node;
      continue;
    }
    Aabb center_box;
    for (Index i = 0; i < task.count; ++i) center_box.extend(centers[begin[i]]);
    int axis = 0;
    (center_box.max - center_box.min).maxCoeff(&axis);
    const Index half = task.count / 2;
    // Ties broken by id so the tree depends only on the input.
    std::nth_element(begin, begin + half, begin + task.count, [&](Index a, Index b) {
      return centers[a][axis] < centers[b][axis] || (centers[a][axis] == centers[b][axis] && a < b);
    });
    // Pre-order numbering: the left subtree (2*half-1 nodes) follows its parent, the
    // right subtree follows the whole left subtree.
    const Index left = task.node + 1;
    const Index right = task.node + 2 * half;
    m_left[task.node] = left;
    m_right[task.node] = right;
    stack.push_back({right, task.first + half, task.count - half, task.node});
    stack.push_back({left, task.first, half, task.node});
  }
  refit(primitive_boxes);
}

void Bvh::refit(std::span<const Aabb> primitive_boxes) {
  for_each_node_bottom_up([&](Index node) {
    if (is_leaf(node)) {
      m_boxes[node] = primitive_boxes[primitive(node)];
    } else {
      m_boxes[node] = m_boxes[m_left[node]];
      m_boxes[node].extend(m_boxes[m_right[node]]);
    }
  });
}

}  // namespace tailor

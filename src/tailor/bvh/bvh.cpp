#include "tailor/bvh/bvh.hpp"

#include "tailor/bvh/bvh_layout.hpp"

namespace tailor {

template <class Box>
BasicBvh<Box>::BasicBvh(std::span<const Box> primitive_boxes) {
  const Index n = static_cast<Index>(primitive_boxes.size());
  if (n == 0) return;
  std::vector<Vec3> centers(static_cast<std::size_t>(n));
  for (Index p = 0; p < n; ++p) centers[p] = primitive_boxes[p].center();
  BvhLayout layout = build_median_split_layout(centers);
  const Index num_nodes = layout.num_nodes();
  m_left.assign(num_nodes, -1);
  m_right = std::move(layout.right);
  m_count = std::move(layout.count);
  m_parent.assign(num_nodes, -1);
  m_first.assign(num_nodes, 0);
  m_boxes.resize(num_nodes);
  if constexpr (kColumns) m_columns.resize(3, n);
  m_leaf_of_primitive.assign(n, -1);
  m_primitive_order.resize(n);
  // Parents precede children, so first offsets and parents fill in one forward pass.
  for (Index node = 0; node < num_nodes; ++node) {
    if (m_count[node] == 1) {
      m_primitive_order[m_first[node]] = m_right[node];
      m_leaf_of_primitive[m_right[node]] = node;
      continue;
    }
    const Index left = node + 1, right = m_right[node];
    m_left[node] = left;
    m_parent[left] = m_parent[right] = node;
    m_first[left] = m_first[node];
    m_first[right] = m_first[node] + m_count[left];
  }
  refit(primitive_boxes);
}

template <class Box>
void BasicBvh<Box>::refit(std::span<const Box> primitive_boxes) {
  for_each_node_bottom_up([&](Index node) {
    if (is_leaf(node)) {
      m_boxes[node] = primitive_boxes[primitive(node)];
      if constexpr (kColumns) m_columns.set(m_first[node], m_boxes[node]);
    } else {
      m_boxes[node] = m_boxes[m_left[node]];
      m_boxes[node].extend(m_boxes[m_right[node]]);
    }
  });
}

template class BasicBvh<Aabb>;
template class BasicBvh<StepBox>;

}  // namespace tailor

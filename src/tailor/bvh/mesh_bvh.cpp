#include "tailor/bvh/mesh_bvh.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

namespace tailor {
namespace {

// Subtrees with more faces than this are refitted as two parallel tasks.
constexpr Index kParallelGrain = 4096;

}  // namespace

MeshBvh::MeshBvh(const TriangleMesh& mesh, const Positions& x_build, std::vector<Index> faces)
    : m_mesh(&mesh), m_faces(std::move(faces)) {
  if (m_faces.empty()) {
    m_faces.resize(static_cast<std::size_t>(mesh.num_faces()));
    std::iota(m_faces.begin(), m_faces.end(), 0);
  }
  std::vector<Vec3> centers(m_faces.size());
  for (std::size_t p = 0; p < m_faces.size(); ++p) {
    const auto v = mesh.faces().row(m_faces[p]);
    const Eigen::Array3d low =
        x_build.row(v[0]).array().min(x_build.row(v[1]).array()).min(x_build.row(v[2]).array());
    const Eigen::Array3d high =
        x_build.row(v[0]).array().max(x_build.row(v[1]).array()).max(x_build.row(v[2]).array());
    centers[p] = (0.5 * (low + high)).matrix();
  }
  BvhLayout layout = build_surface_layout(mesh, m_faces, centers);
  centers = {};
  const Index n = layout.num_nodes();
  m_nodes.resize(static_cast<std::size_t>(n));
  m_cone_slot.assign(static_cast<std::size_t>(n), -1);
  Index cones = 0;
  for (Index node = 0; node < n; ++node) {
    m_nodes[node].count = layout.count[node];
    if (layout.is_leaf(node)) {
      m_nodes[node].right_or_face = m_faces[layout.right[node]];
      continue;
    }
    m_nodes[node].right_or_face = layout.right[node];
    // Inner nodes with a cone: the large ones, and the roots of small subtrees.
    if (layout.count[node] >= kDirectConeFaces) {
      m_cone_slot[node] = cones++;
      for (Index child : {node + 1, layout.right[node]}) {
        if (!layout.is_leaf(child) && layout.count[child] < kDirectConeFaces) {
          m_cone_slot[child] = cones++;
        }
      }
    } else if (node == 0) {
      m_cone_slot[node] = cones++;
    }
  }
  m_cones.assign(static_cast<std::size_t>(cones), NormalCone::wide());
  // Task roots: the largest subtrees of at most kParallelGrain faces; the nodes above
  // them are refitted after them, in decreasing id order.
  enum : char { kBelow, kTaskRoot, kTopNode };
  std::vector<char> role(static_cast<std::size_t>(n), kBelow);
  std::vector<Index> stack{0};
  while (!stack.empty()) {
    const Index node = stack.back();
    stack.pop_back();
    if (size(node) <= kParallelGrain) {
      role[node] = kTaskRoot;
    } else {
      role[node] = kTopNode;
      stack.push_back(right(node));
      stack.push_back(node + 1);
    }
  }
  // Corners in leaf order (= increasing id), and the leaves before each task root.
  m_leaf_vertices.reserve(m_faces.size());
  for (Index node = 0; node < n; ++node) {
    const TaskRoot root{node, static_cast<Index>(m_leaf_vertices.size())};
    if (role[node] == kTaskRoot) m_task_roots.push_back(root);
    if (role[node] == kTopNode) m_top_nodes.push_back(root);
    if (is_leaf(node)) {
      const auto v = mesh.faces().row(leaf_face(node));
      m_leaf_vertices.push_back({v[0], v[1], v[2]});
    }
  }
  std::reverse(m_top_nodes.begin(), m_top_nodes.end());
  refit(x_build, x_build, false);
}

void MeshBvh::refit(const Positions& x0, const Positions& x1, bool with_cones) {
  if (m_nodes.empty()) return;
  tbb::parallel_for(std::size_t{0}, m_task_roots.size(), [&](std::size_t i) {
    const TaskRoot& root = m_task_roots[i];
    refit_range(root.node, root.node + 2 * size(root.node) - 1, root.leaves_before, x0, x1,
                with_cones);
  });
  for (const TaskRoot& top : m_top_nodes) {
    refit_range(top.node, top.node + 1, top.leaves_before, x0, x1, with_cones);
  }
}

NormalCone MeshBvh::direct_cone(Index first_leaf, Index count, const Positions& x0,
                                const Positions& x1) const {
  MovingTriangle triangles[kDirectConeFaces];
  for (Index i = 0; i < count; ++i) {
    const auto& v = m_leaf_vertices[first_leaf + i];
    triangles[i] = {&x0(v[0], 0), &x0(v[1], 0), &x0(v[2], 0),
                    &x1(v[0], 0), &x1(v[1], 0), &x1(v[2], 0)};
  }
  return continuous_normal_cone(
      std::span<const MovingTriangle>(triangles, static_cast<std::size_t>(count)));
}

void MeshBvh::refit_range(Index begin, Index end, Index leaves_before, const Positions& x0,
                          const Positions& x1, bool with_cones) {
  // Leaves of the range in decreasing order too; `leaf` is the next one to visit (a
  // whole subtree of s faces has 2s - 1 nodes and s leaves; one inner node none).
  const Index leaves = is_leaf(begin) || end - begin > 1 ? (end - begin + 1) / 2 : 0;
  Index leaf = leaves_before + leaves - 1;
  for (Index node = end - 1; node >= begin; --node) {
    Node& record = m_nodes[node];
    if (record.count == 1) {
      const auto& v = m_leaf_vertices[leaf--];
      const double* p[6] = {&x0(v[0], 0), &x0(v[1], 0), &x0(v[2], 0),
                            &x1(v[0], 0), &x1(v[1], 0), &x1(v[2], 0)};
      double low[3], high[3];
      for (int k = 0; k < 3; ++k) {
        low[k] = high[k] = p[0][k];
        for (int i = 1; i < 6; ++i) {
          low[k] = p[i][k] < low[k] ? p[i][k] : low[k];
          high[k] = p[i][k] > high[k] ? p[i][k] : high[k];
        }
      }
      record.box = FloatBox::enclosing(low, high);
      continue;
    }
    record.box = m_nodes[node + 1].box;
    record.box.extend(m_nodes[record.right_or_face].box);
    if (!with_cones || m_cone_slot[node] < 0) continue;
    // This node's leaves are the `count` leaves after `leaf`, its left child's first.
    NormalCone& cone = m_cones[m_cone_slot[node]];
    if (record.count < kDirectConeFaces) {
      cone = direct_cone(leaf + 1, record.count, x0, x1);
    } else {
      const Index left = node + 1, right = record.right_or_face;
      const auto child_cone = [&](Index child, Index first_leaf) {
        return m_cone_slot[child] >= 0 ? m_cones[m_cone_slot[child]]
                                       : direct_cone(first_leaf, size(child), x0, x1);
      };
      cone = child_cone(left, leaf + 1).merged(child_cone(right, leaf + 1 + size(left)));
    }
  }
}

}  // namespace tailor

#include "tailor/bvh/mesh_bvh.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace tailor {
namespace {

// Subtrees of at most this many faces are refitted by one task.
constexpr Index kParallelGrain = 4096;

constexpr double kFloatMax = std::numeric_limits<float>::max();

// min and max in the form that compiles to minpd/maxpd (exact for the finite inputs here).
inline double smaller(double a, double b) {
  return b < a ? b : a;
}
inline double larger(double a, double b) {
  return a < b ? b : a;
}

// A double that converts to a float <= x (float_at_most, float_box.hpp), clamped to the
// float range: beyond it a box no longer holds its points, but every overlap is kept (the
// rounding is monotone, so overlapping intervals stay overlapping), which is all the
// traversal asks of boxes. Branch-free, so that loops of it vectorise.
inline double below_in_float_range(double x) {
  return larger(smaller(x - std::fabs(x) * 0x1p-23 - 0x1p-149, kFloatMax), -kFloatMax);
}

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
  for (Index node = 0; node < n; ++node) {
    m_nodes[node].count = layout.count[node];
    m_nodes[node].right_or_face =
        layout.is_leaf(node) ? m_faces[layout.right[node]] : layout.right[node];
  }
  layout = {};

  // Roles, top-down: merge nodes (>= kGroupFaces faces), group roots (the largest subtrees
  // below), task roots (the largest subtrees of at most kParallelGrain faces).
  std::vector<char> group_root(static_cast<std::size_t>(n), 0), task_root(group_root);
  std::vector<Index> stack{0};
  while (!stack.empty()) {
    const Index node = stack.back();
    stack.pop_back();
    if (size(node) < kGroupFaces) {
      group_root[node] = 1;
    } else {
      stack.push_back(right(node));
      stack.push_back(left(node));
    }
  }
  stack.push_back(0);
  while (!stack.empty()) {
    const Index node = stack.back();
    stack.pop_back();
    if (size(node) <= kParallelGrain) {
      task_root[node] = 1;
    } else {
      m_top_merges.push_back(node);
      stack.push_back(right(node));
      stack.push_back(left(node));
    }
  }
  std::sort(m_top_merges.rbegin(), m_top_merges.rend());

  // Slots, groups, merge nodes and the corners in leaf order (= increasing id).
  m_slot.assign(static_cast<std::size_t>(n), -1);
  Index slots = 0;
  m_leaf_vertices.reserve(m_faces.size());
  for (Index node = 0; node < n; ++node) {
    if (group_root[node]) {
      m_slot[node] = slots++;
      m_groups.push_back(
          {node, static_cast<Index>(m_leaf_vertices.size()), static_cast<Index>(m_groups.size())});
      // Its leaves and inner nodes in increasing id order (inner: count - 1 of them).
      for (Index member = node; member < node + 2 * size(node) - 1; ++member) {
        (is_leaf(member) ? m_group_leaf_nodes : m_group_inner_nodes).push_back(member);
      }
    } else if (size(node) >= kGroupFaces) {
      m_slot[node] = slots++;
      m_merge_nodes.push_back(node);
    }
    if (is_leaf(node)) {
      const auto v = mesh.faces().row(leaf_face(node));
      m_leaf_vertices.push_back({v[0], v[1], v[2]});
    }
  }
  m_masks.assign(static_cast<std::size_t>(slots), 0);

  // A task's subtree is the id range [root, root + 2·size - 1): its groups and merge
  // nodes are contiguous in the sorted lists.
  for (Index node = 0; node < n; ++node) {
    if (!task_root[node]) continue;
    const Index end = node + 2 * size(node) - 1;
    const auto group_at = [&](Index id) {
      return static_cast<Index>(
          std::lower_bound(m_groups.begin(), m_groups.end(), id,
                           [](const Group& g, Index x) { return g.root < x; }) -
          m_groups.begin());
    };
    const auto merge_at = [&](Index id) {
      return static_cast<Index>(std::lower_bound(m_merge_nodes.begin(), m_merge_nodes.end(), id) -
                                m_merge_nodes.begin());
    };
    m_tasks.push_back({group_at(node), group_at(end), merge_at(node), merge_at(end)});
  }
  refit(x_build, x_build, false);
}

void MeshBvh::refit(const Positions& x0, const Positions& x1, bool with_directions) {
  if (m_nodes.empty()) return;
  tbb::parallel_for(std::size_t{0}, m_tasks.size(), [&](std::size_t t) {
    const Task& task = m_tasks[t];
    for (Index g = task.groups_begin; g < task.groups_end; ++g) {
      refit_group(m_groups[g], x0, x1, with_directions);
    }
    for (Index k = task.merges_end - 1; k >= task.merges_begin; --k) {
      merge(m_merge_nodes[k], with_directions);
    }
  });
  for (Index node : m_top_merges) merge(node, with_directions);
}

void MeshBvh::refit_group(const Group& group, const Positions& x0, const Positions& x1,
                          bool with_directions) {
  const Index count = size(group.root);
  const double* p0 = x0.data();
  const double* p1 = x1.data();
  MovingTriangleBatch batch;
  // Leaf boxes straight from the corners (leaves in increasing id order), rounded outward.
  const Index* leaf_node = m_group_leaf_nodes.data() + group.first_leaf;
  for (Index l = 0; l < count; ++l) {
    const auto& v = m_leaf_vertices[group.first_leaf + l];
    const double* corner[6] = {p0 + 3 * v[0], p0 + 3 * v[1], p0 + 3 * v[2],
                               p1 + 3 * v[0], p1 + 3 * v[1], p1 + 3 * v[2]};
    FloatBox& box = m_nodes[leaf_node[l]].box;
    for (int k = 0; k < 3; ++k) {
      double lo = corner[0][k], hi = lo;
      for (int c = 1; c < 6; ++c) {
        lo = smaller(lo, corner[c][k]);
        hi = larger(hi, corner[c][k]);
      }
      box.min[k] = static_cast<float>(below_in_float_range(lo));
      box.max[k] = static_cast<float>(-below_in_float_range(-hi));
    }
    if (with_directions)
      batch.add(corner[0], corner[1], corner[2], corner[3], corner[4], corner[5]);
  }
  // The group's inner nodes, children first.
  // (A one-face group has no inner node, and the list may be empty: no indexing.)
  const Index* inner = m_group_inner_nodes.data() + (group.first_leaf - group.index);
  for (Index i = count - 2; i >= 0; --i) {
    Node& record = m_nodes[inner[i]];
    record.box = m_nodes[inner[i] + 1].box;
    record.box.extend(m_nodes[record.right_or_face].box);
  }
  if (with_directions) {
    batch.pad();
    m_masks[m_slot[group.root]] = tailor::direction_mask(batch);
  }
}

void MeshBvh::merge(Index node, bool with_directions) {
  Node& record = m_nodes[node];
  record.box = m_nodes[node + 1].box;
  record.box.extend(m_nodes[record.right_or_face].box);
  if (with_directions) {
    m_masks[m_slot[node]] = m_masks[m_slot[node + 1]] & m_masks[m_slot[record.right_or_face]];
  }
}

}  // namespace tailor

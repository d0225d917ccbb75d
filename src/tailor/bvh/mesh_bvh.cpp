#include "tailor/bvh/mesh_bvh.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <numeric>

#include "tailor/bvh/batch_bounds.hpp"
#include "tailor/bvh/batch_gather.hpp"
#include "tailor/bvh/diagonal_bounds.hpp"
#include "tailor/bvh/group_boxes.hpp"

namespace tailor {
namespace {

// Subtrees of at most this many faces are refitted by one task.
constexpr Index kParallelGrain = 4096;

// How many leaves ahead the refit prefetches corners (about three groups: on the Zen 5,
// BM_RefitOnly of 1M triangles on one thread took 16.0-16.2 ms with 16, 14.8-15.6 with 48,
// as with 64).
constexpr Index kPrefetchLeaves = 48;
// How many groups ahead it prefetches node records.
constexpr Index kPrefetchGroups = 2;

}  // namespace

MeshBvh::MeshBvh(const TriangleMesh& mesh, const Positions& x_build, std::vector<Index> faces) {
  if (faces.empty()) {
    faces.resize(static_cast<std::size_t>(mesh.num_faces()));
    std::iota(faces.begin(), faces.end(), 0);
  }
  build_nodes(mesh, x_build, std::move(faces));
  const Roles roles = mark_roles();
  assign_slots(mesh, roles);
  index_tasks(roles);
  refit(x_build, x_build, false);
}

void MeshBvh::build_nodes(const TriangleMesh& mesh, const Positions& x_build,
                          std::vector<Index> faces) {
  std::vector<Vec3> centers(faces.size());
  for (std::size_t p = 0; p < faces.size(); ++p) {
    const auto v = mesh.faces().row(faces[p]);
    const Eigen::Array3d low =
        x_build.row(v[0]).array().min(x_build.row(v[1]).array()).min(x_build.row(v[2]).array());
    const Eigen::Array3d high =
        x_build.row(v[0]).array().max(x_build.row(v[1]).array()).max(x_build.row(v[2]).array());
    centers[p] = (0.5 * (low + high)).matrix();
  }
  const BvhLayout layout = build_surface_layout(mesh, faces, centers);
  const Index n = layout.num_nodes();
  m_nodes.resize(static_cast<std::size_t>(n));  // unwritten: each record is built here
  tbb::parallel_for(tbb::blocked_range<Index>(0, n, 4096), [&](const auto& range) {
    for (Index node = range.begin(); node < range.end(); ++node) {
      Node* record = ::new (static_cast<void*>(&m_nodes[node])) Node;
      record->count = layout.count[node];
      record->right_or_face = layout.is_leaf(node) ? faces[layout.right[node]] : layout.right[node];
    }
  });
}

MeshBvh::Roles MeshBvh::mark_roles() {
  // Top-down: merge nodes (>= kGroupFaces faces), group roots (the largest subtrees
  // below), task roots (the largest subtrees of at most kParallelGrain faces).
  const auto n = static_cast<std::size_t>(num_nodes());
  Roles roles{std::vector<char>(n, 0), std::vector<char>(n, 0)};
  std::vector<Index> stack{0};
  while (!stack.empty()) {
    const Index node = stack.back();
    stack.pop_back();
    if (size(node) < kGroupFaces) {
      roles.group_root[node] = 1;
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
      roles.task_root[node] = 1;
    } else {
      m_top_merges.push_back(node);
      stack.push_back(right(node));
      stack.push_back(left(node));
    }
  }
  std::sort(m_top_merges.rbegin(), m_top_merges.rend());
  return roles;
}

void MeshBvh::assign_slots(const TriangleMesh& mesh, const Roles& roles) {
  // Slots, groups, merge nodes and the corners in leaf order (= increasing id).
  const Index n = num_nodes();
  const std::size_t words = (static_cast<std::size_t>(n) + 63) / 64;
  m_mask_bits.assign(words, 0);
  m_masks_before_word.assign(words, 0);
  Index slots = 0;
  m_leaf_vertices.reserve(static_cast<std::size_t>(n + 1) / 2);
  m_leaf_faces.reserve(static_cast<std::size_t>(n + 1) / 2);
  for (Index node = 0; node < n; ++node) {
    // Pre-order: the leaves before `node` in id order are the leaves before its subtree.
    m_nodes[node].first_leaf = static_cast<Index>(m_leaf_vertices.size());
    const std::size_t word = static_cast<std::size_t>(node) >> 6;
    if ((node & 63) == 0) m_masks_before_word[word] = slots;
    const bool merges = !roles.group_root[node] && size(node) >= kGroupFaces;
    const Index slot = slots;
    if (roles.group_root[node] || merges) {
      m_mask_bits[word] |= std::uint64_t{1} << (node & 63);
      ++slots;
    }
    if (roles.group_root[node]) {
      std::uint32_t leaf_bits = 0;
      for (Index member = node; member < node + 2 * size(node) - 1; ++member) {
        if (is_leaf(member)) leaf_bits |= std::uint32_t{1} << (member - node);
      }
      m_groups.push_back({node, static_cast<Index>(m_leaf_vertices.size()), slot, leaf_bits});
    } else if (merges) {
      m_merges.push_back({node, slot, -1, -1});
    }
    if (is_leaf(node)) {
      const auto v = mesh.faces().row(leaf_face(node));
      m_leaf_vertices.push_back({v[0], v[1], v[2]});
      m_leaf_faces.push_back(leaf_face(node));
    }
  }
  m_leaf_bounds.resize(StepBoundColumns::kMaxDirections, static_cast<Index>(m_leaf_faces.size()));
  m_masks.assign(static_cast<std::size_t>(slots), 0);
  // A merge node's children are merge nodes or group roots: both keep a mask.
  for (Merge& merge : m_merges) {
    merge.left_slot = mask_index(left(merge.node));
    merge.right_slot = mask_index(right(merge.node));
  }
}

void MeshBvh::index_tasks(const Roles& roles) {
  const auto merge_at = [&](Index id) {
    return static_cast<Index>(std::lower_bound(m_merges.begin(), m_merges.end(), id,
                                               [](const Merge& m, Index x) { return m.node < x; }) -
                              m_merges.begin());
  };
  const auto group_at = [&](Index id) {
    return static_cast<Index>(std::lower_bound(m_groups.begin(), m_groups.end(), id,
                                               [](const Group& g, Index x) { return g.root < x; }) -
                              m_groups.begin());
  };
  for (Index& node : m_top_merges) node = merge_at(node);  // node ids to positions
  // A task's subtree is the id range [root, root + 2·size - 1): its groups and merge
  // nodes are contiguous in the sorted lists.
  for (Index node = 0; node < num_nodes(); ++node) {
    if (!roles.task_root[node]) continue;
    const Index end = node + 2 * size(node) - 1;
    m_tasks.push_back({group_at(node), group_at(end), merge_at(node), merge_at(end)});
  }
}

void MeshBvh::refit(const Positions& x0, const Positions& x1, bool with_directions,
                    bool with_diagonals) {
  refit_parts(x0, x1, {true, with_diagonals, with_directions});
  m_boxes_current = true;
  m_diagonals_current = with_diagonals;
}

void MeshBvh::refit_directions(const Positions& x0, const Positions& x1) {
  refit_parts(x0, x1, {false, false, true});
  m_boxes_current = m_diagonals_current = false;
}

void MeshBvh::refit_parts(const Positions& x0, const Positions& x1, RefitParts parts) {
  if (m_nodes.empty()) return;
  tbb::parallel_for(std::size_t{0}, m_tasks.size(), [&](std::size_t t) {
    const Task& task = m_tasks[t];
    // Consecutive groups share a batch while their faces fit: the kernels cost about as
    // much for a few lanes as for a whole batch, and a sixth of the crumpling cloth's
    // groups hold a single face (a node of 17 faces splits into 16 and 1).
    for (Index first = task.groups_begin; first < task.groups_end;) {
      Index end = first + 1;
      Index faces = group_faces(first);
      while (end < task.groups_end && faces + group_faces(end) <= MovingTriangleBatch::kCapacity) {
        faces += group_faces(end++);
      }
      refit_groups(first, end, faces, x0, x1, parts);
      first = end;
    }
    for (Index k = task.merges_end - 1; k >= task.merges_begin; --k) {
      merge(m_merges[k], parts);
    }
  });
  for (Index k : m_top_merges) merge(m_merges[k], parts);
}

Index MeshBvh::group_faces(Index g) const {
  const Index next = g + 1 < static_cast<Index>(m_groups.size())
                         ? m_groups[static_cast<std::size_t>(g) + 1].first_leaf
                         : static_cast<Index>(m_leaf_vertices.size());
  return next - m_groups[static_cast<std::size_t>(g)].first_leaf;
}

void MeshBvh::refit_groups(Index first, Index end, Index faces, const Positions& x0,
                           const Positions& x1, RefitParts parts) {
  const double* p0 = x0.data();
  const double* p1 = x1.data();
  const Index leaves = static_cast<Index>(m_leaf_vertices.size());
  const Index groups = static_cast<Index>(m_groups.size());
  const Index first_leaf = m_groups[first].first_leaf;
  // The corners of the groups' faces in structure-of-arrays form (leaves in increasing id
  // order), from which the boxes and the masks are computed in vectorisable loops.
  MovingTriangleBatch batch;
  // The node records of the groups kPrefetchGroups ahead, which will be written: 128 bytes
  // per face, not in cache. (Their face counts from m_groups: reading a root record would
  // wait for memory.)
  const Index prefetch_groups_end = parts.boxes ? std::min(end + kPrefetchGroups, groups) : 0;
  for (Index ahead = first + kPrefetchGroups; ahead < prefetch_groups_end; ++ahead) {
    const Node* record = &m_nodes[m_groups[ahead].root];
    const char* stop = reinterpret_cast<const char*>(record + 2 * group_faces(ahead) - 1);
    for (const char* line = reinterpret_cast<const char*>(record); line < stop; line += 64) {
      __builtin_prefetch(line, 1);
    }
  }
  // The corners are gathered in leaf order, which the hardware prefetcher cannot follow:
  // without this the refit waits on memory (1M-face cloth: 42 ms against 33 ms).
  const Index prefetch_end = std::min(leaves, first_leaf + faces + kPrefetchLeaves);
  for (Index ahead = first_leaf + kPrefetchLeaves; ahead < prefetch_end; ++ahead) {
    for (const Index u : m_leaf_vertices[ahead]) {
      __builtin_prefetch(p0 + 3 * u);
      __builtin_prefetch(p1 + 3 * u);
    }
  }
  gather_batch(p0, p1,
               std::span(m_leaf_vertices)
                   .subspan(static_cast<std::size_t>(first_leaf), static_cast<std::size_t>(faces)),
               batch);
  // Leaf boxes: per frame, coordinate and lane, the three corners' extremes, rounded
  // outward.
  BatchBounds start, end_bounds;
  DiagonalBatchBounds diagonal_start, diagonal_end;
  if (parts.boxes) batch_bounds(batch, start, end_bounds);
  if (parts.diagonals) diagonal_batch_bounds(batch, diagonal_start, diagonal_end);
  LaneMasks masks;
  if (parts.directions) lane_masks(batch, masks);
  // Each group's nodes are the id range [root, root + 2·count - 1) (pre-order): its leaves
  // in increasing id order are consecutive lanes of the batch.
  static_assert(offsetof(Node, right_or_face) == sizeof(FloatBox) && offsetof(Node, end) == 32 &&
                    offsetof(Node, diagonal_start) == 64 && offsetof(Node, diagonal_end) == 96 &&
                    sizeof(Node) == 128,
                "write_group_boxes() writes 32 bytes from each box");
  if (parts.boxes) write_leaf_bounds(first_leaf, faces, start, end_bounds);
  if (parts.diagonals) write_leaf_diagonal_bounds(first_leaf, faces, diagonal_start, diagonal_end);
  int lane = 0;
  for (Index g = first; g < end; ++g) {
    const Group& group = m_groups[g];
    const int count = static_cast<int>(group_faces(g));
    if (parts.boxes) {
      write_group_boxes(start, lane, group.leaf_bits, count, &m_nodes[group.root].start,
                        sizeof(Node));
      write_group_boxes(end_bounds, lane, group.leaf_bits, count, &m_nodes[group.root].end,
                        sizeof(Node));
    }
    if (parts.diagonals) {
      write_group_diagonal_boxes(diagonal_start, lane, group.leaf_bits, count,
                                 &m_nodes[group.root].diagonal_start, sizeof(Node));
      write_group_diagonal_boxes(diagonal_end, lane, group.leaf_bits, count,
                                 &m_nodes[group.root].diagonal_end, sizeof(Node));
    }
    if (parts.directions) m_masks[group.mask_slot] = and_of_masks(masks, lane, lane + count);
    lane += count;
  }
}

void MeshBvh::write_leaf_bounds(Index first_leaf, Index faces, const BatchBounds& start,
                                const BatchBounds& end) {
  const auto n = static_cast<std::size_t>(faces);
  for (int k = 0; k < 3; ++k) {
    std::copy_n(start.low[k], n, m_leaf_bounds.column(k, StepBoundColumns::kStartMin) + first_leaf);
    std::copy_n(start.high[k], n,
                m_leaf_bounds.column(k, StepBoundColumns::kStartMax) + first_leaf);
    std::copy_n(end.low[k], n, m_leaf_bounds.column(k, StepBoundColumns::kEndMin) + first_leaf);
    std::copy_n(end.high[k], n, m_leaf_bounds.column(k, StepBoundColumns::kEndMax) + first_leaf);
  }
}

void MeshBvh::write_leaf_diagonal_bounds(Index first_leaf, Index faces,
                                         const DiagonalBatchBounds& start,
                                         const DiagonalBatchBounds& end) {
  const auto n = static_cast<std::size_t>(faces);
  for (int k = 0; k < kDiagonals; ++k) {
    const int d = 3 + k;
    std::copy_n(start.low[k], n, m_leaf_bounds.column(d, StepBoundColumns::kStartMin) + first_leaf);
    std::copy_n(start.high[k], n,
                m_leaf_bounds.column(d, StepBoundColumns::kStartMax) + first_leaf);
    std::copy_n(end.low[k], n, m_leaf_bounds.column(d, StepBoundColumns::kEndMin) + first_leaf);
    std::copy_n(end.high[k], n, m_leaf_bounds.column(d, StepBoundColumns::kEndMax) + first_leaf);
  }
}

void MeshBvh::join_children(Index node, bool diagonals) {
  // Component by component: a child that is a merge node was just written a float at a
  // time, and a wider load of it would wait for those stores (a failed store-to-load
  // forward).
  Node& record = m_nodes[node];
  const Node& left = m_nodes[node + 1];
  const Node& right = m_nodes[record.right_or_face];
  const auto join = [](auto& box, const auto& a, const auto& b) {
    for (std::size_t k = 0; k < box.min.size(); ++k) {
      box.min[k] = b.min[k] < a.min[k] ? b.min[k] : a.min[k];
      box.max[k] = b.max[k] > a.max[k] ? b.max[k] : a.max[k];
    }
  };
  join(record.start, left.start, right.start);
  join(record.end, left.end, right.end);
  if (!diagonals) return;
  join(record.diagonal_start, left.diagonal_start, right.diagonal_start);
  join(record.diagonal_end, left.diagonal_end, right.diagonal_end);
}

void MeshBvh::merge(const Merge& merge, RefitParts parts) {
  if (parts.boxes) join_children(merge.node, parts.diagonals);
  if (parts.directions) {
    m_masks[merge.slot] = m_masks[merge.left_slot] & m_masks[merge.right_slot];
  }
}

}  // namespace tailor

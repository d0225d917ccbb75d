#include "tailor/culling/node_contours.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>

namespace tailor {
namespace {

// A boundary half-edge of a patch, directed by its face's orientation.
struct HalfEdge {
  Index edge, from, to;
};

// The loops one thread recorded: their vertices, one after another, and where each is.
struct LoopBuffer {
  struct Loop {
    Index slot;
    std::int64_t start;
    Index length;
  };
  std::vector<Index> vertices;
  std::vector<Loop> loops;
  // Per vertex: the successor on the loop being recorded, valid where stamp is its slot.
  std::vector<Index> next, stamp;
};

// Builds bottom-up; subtrees of more than kParallelAbove faces build their two children
// in parallel, each thread recording loops in its own buffer.
struct ContourBuilder {
  static constexpr Index kParallelAbove = 4096;

  const TriangleMesh& mesh;
  const MeshBvh& bvh;
  tbb::enumerable_thread_specific<LoopBuffer> buffers;

  // Returns the node's boundary half-edges sorted by edge id; `valid` turns false when
  // the patch is not edge-manifold or not consistently oriented.
  std::vector<HalfEdge> build(Index node, bool& valid) {
    std::vector<HalfEdge> boundary;
    if (bvh.size(node) < MeshBvh::kGroupFaces) {
      boundary = group_boundary(node, valid);
    } else {
      bool left_valid = true, right_valid = true;
      std::vector<HalfEdge> left, right;
      if (bvh.size(node) > kParallelAbove) {
        tbb::parallel_invoke([&] { left = build(bvh.left(node), left_valid); },
                             [&] { right = build(bvh.right(node), right_valid); });
      } else {
        left = build(bvh.left(node), left_valid);
        right = build(bvh.right(node), right_valid);
      }
      valid = left_valid && right_valid;
      boundary = std::move(left);
      const auto middle = static_cast<std::ptrdiff_t>(boundary.size());
      boundary.insert(boundary.end(), right.begin(), right.end());
      std::inplace_merge(boundary.begin(), boundary.begin() + middle, boundary.end(), by_edge);
      if (!drop_interior(boundary)) valid = false;
    }
    // Only nodes with a mask are ever tested (leaves never: a triangle cannot touch
    // itself).
    if (bvh.has_mask(node) && valid) record_loop(bvh.mask_index(node), boundary);
    return boundary;
  }

  static bool by_edge(const HalfEdge& a, const HalfEdge& b) { return a.edge < b.edge; }

  // Removes both half-edges of every edge listed twice in `sorted` (by edge): the edge is
  // interior. False when two such half-edges run the same way (the faces are not
  // consistently oriented).
  static bool drop_interior(std::vector<HalfEdge>& sorted) {
    bool consistent = true;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      if (i + 1 < sorted.size() && sorted[i + 1].edge == sorted[i].edge) {
        if (sorted[i].from != sorted[i + 1].to) consistent = false;
        ++i;  // interior: both copies go
      } else {
        sorted[kept++] = sorted[i];
      }
    }
    sorted.resize(kept);
    return consistent;
  }

  // The boundary of a node of fewer than kGroupFaces faces (a group or a node inside one:
  // none below it keeps a mask) straight from its faces' half-edges, without a vector per
  // node.
  std::vector<HalfEdge> group_boundary(Index node, bool& valid) const {
    std::vector<HalfEdge> half_edges;
    half_edges.reserve(3 * static_cast<std::size_t>(bvh.size(node)));
    for (Index n = node; n < node + 2 * bvh.size(node) - 1; ++n) {
      if (!bvh.is_leaf(n)) continue;
      const Index f = bvh.leaf_face(n);
      const auto edges = mesh.face_edges(f);
      for (int i = 0; i < 3; ++i) {
        if (mesh.edge_faces(edges[i]).size() > 2) valid = false;  // non-manifold edge
        half_edges.push_back({edges[i], mesh.faces()(f, i), mesh.faces()(f, (i + 1) % 3)});
      }
    }
    std::sort(half_edges.begin(), half_edges.end(), by_edge);
    if (!drop_interior(half_edges)) valid = false;
    return half_edges;
  }

  // Stores the loop if the half-edges form exactly one cycle visiting each vertex once.
  // The successor of each vertex goes in the thread's per-vertex table, stamped with the
  // slot (unique to this node), so nothing is cleared or sorted.
  void record_loop(Index slot, const std::vector<HalfEdge>& half_edges) {
    if (half_edges.size() < 3) return;
    LoopBuffer& buffer = buffers.local();
    if (buffer.stamp.empty()) {
      buffer.stamp.assign(static_cast<std::size_t>(mesh.num_vertices()), -1);
      buffer.next.resize(static_cast<std::size_t>(mesh.num_vertices()));
    }
    for (const HalfEdge& h : half_edges) {
      if (buffer.stamp[h.from] == slot) return;  // vertex visited twice
      buffer.stamp[h.from] = slot;
      buffer.next[h.from] = h.to;
    }
    const auto next = [&](Index v) -> Index {
      return buffer.stamp[v] == slot ? buffer.next[v] : -1;
    };
    std::vector<Index>& vertices = buffer.vertices;
    const std::int64_t start_at = static_cast<std::int64_t>(vertices.size());
    const Index start =
        std::min_element(half_edges.begin(), half_edges.end(),
                         [](const HalfEdge& a, const HalfEdge& b) { return a.from < b.from; })
            ->from;
    Index v = start;
    std::size_t steps = 0;
    do {
      vertices.push_back(v);
      v = next(v);
      ++steps;
    } while (v >= 0 && v != start && steps <= half_edges.size());
    if (v != start || steps != half_edges.size()) {
      vertices.resize(static_cast<std::size_t>(start_at));  // open chain or several loops
      return;
    }
    buffer.loops.push_back({slot, start_at, static_cast<Index>(steps)});
  }
};

}  // namespace

NodeContours::NodeContours(const TriangleMesh& mesh, const MeshBvh& bvh) {
  const Index n = bvh.num_nodes();
  m_bvh = &bvh;
  m_loop_start.assign(static_cast<std::size_t>(bvh.num_masks()), 0);
  m_loop_length.assign(static_cast<std::size_t>(bvh.num_masks()), 0);
  if (n == 0) return;
  ContourBuilder builder{mesh, bvh, {}};
  bool valid = true;
  builder.build(0, valid);
  // One array of loop vertices; a loop's place in it depends on the scheduling, the loop
  // of each node does not.
  for (const LoopBuffer& buffer : builder.buffers) {
    const auto base = static_cast<std::int64_t>(m_loop_vertices.size());
    m_loop_vertices.insert(m_loop_vertices.end(), buffer.vertices.begin(), buffer.vertices.end());
    for (const LoopBuffer::Loop& loop : buffer.loops) {
      m_loop_start[loop.slot] = base + loop.start;
      m_loop_length[loop.slot] = loop.length;
    }
  }
  m_loop_vertices.shrink_to_fit();
}

}  // namespace tailor

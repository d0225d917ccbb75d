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
    if (bvh.is_leaf(node)) {
      const Index f = bvh.leaf_face(node);
      const auto edges = mesh.face_edges(f);
      for (int i = 0; i < 3; ++i) {
        if (mesh.edge_faces(edges[i]).size() > 2) valid = false;  // non-manifold edge
        boundary.push_back({edges[i], mesh.faces()(f, i), mesh.faces()(f, (i + 1) % 3)});
      }
      std::sort(boundary.begin(), boundary.end(),
                [](const HalfEdge& a, const HalfEdge& b) { return a.edge < b.edge; });
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
      boundary.reserve(left.size() + right.size());
      // Merge; an edge on both sides is interior now, and must be traversed in opposite
      // directions by its two faces (consistent orientation).
      std::size_t i = 0, j = 0;
      while (i < left.size() || j < right.size()) {
        if (j == right.size() || (i < left.size() && left[i].edge < right[j].edge)) {
          boundary.push_back(left[i++]);
        } else if (i == left.size() || right[j].edge < left[i].edge) {
          boundary.push_back(right[j++]);
        } else {
          if (left[i].from != right[j].to) valid = false;
          ++i, ++j;
        }
      }
    }
    // Only nodes with a mask are ever tested (leaves never: a triangle cannot touch
    // itself).
    if (bvh.has_mask(node) && valid) record_loop(bvh.mask_index(node), boundary);
    return boundary;
  }

  // Stores the loop if the half-edges form exactly one cycle visiting each vertex once.
  void record_loop(Index slot, std::vector<HalfEdge> half_edges) {
    if (half_edges.size() < 3) return;
    std::sort(half_edges.begin(), half_edges.end(),
              [](const HalfEdge& a, const HalfEdge& b) { return a.from < b.from; });
    for (std::size_t k = 1; k < half_edges.size(); ++k) {
      if (half_edges[k].from == half_edges[k - 1].from) return;  // vertex visited twice
    }
    auto next = [&](Index v) -> Index {
      auto it = std::lower_bound(half_edges.begin(), half_edges.end(), v,
                                 [](const HalfEdge& h, Index x) { return h.from < x; });
      return (it == half_edges.end() || it->from != v) ? -1 : it->to;
    };
    LoopBuffer& buffer = buffers.local();
    std::vector<Index>& vertices = buffer.vertices;
    const std::int64_t start_at = static_cast<std::int64_t>(vertices.size());
    const Index start = half_edges.front().from;
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

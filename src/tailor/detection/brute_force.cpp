#include "tailor/detection/brute_force.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

#include "tailor/bvh/aabb.hpp"
#include "tailor/detection/exact_pair_tests.hpp"

namespace tailor {
namespace {

// Boxes sorted by their lower x, for the ones whose x-range meets a query range.
class SortedBoxes {
 public:
  explicit SortedBoxes(std::vector<Aabb> boxes) : m_boxes(std::move(boxes)) {
    m_order.resize(m_boxes.size());
    std::iota(m_order.begin(), m_order.end(), 0);
    std::sort(m_order.begin(), m_order.end(),
              [&](Index a, Index b) { return m_boxes[a].min.x() < m_boxes[b].min.x(); });
    for (const Aabb& box : m_boxes) m_max_width = std::max(m_max_width, box.max.x() - box.min.x());
  }
  const Aabb& box(Index i) const { return m_boxes[static_cast<std::size_t>(i)]; }
  // Calls visit(i) for every box overlapping `query` (closed boxes).
  template <class Visit>
  void for_each_overlapping(const Aabb& query, Visit&& visit) const {
    const double from = query.min.x() - m_max_width;
    auto it = std::lower_bound(m_order.begin(), m_order.end(), from,
                               [&](Index i, double x) { return m_boxes[i].min.x() < x; });
    for (; it != m_order.end() && m_boxes[*it].min.x() <= query.max.x(); ++it) {
      if (m_boxes[*it].overlaps(query)) visit(*it);
    }
  }

 private:
  std::vector<Aabb> m_boxes;
  std::vector<Index> m_order;
  double m_max_width = 0;
};

}  // namespace

CollisionSet brute_force_self_collisions(const TriangleMesh& mesh, const Positions& x0,
                                         const Positions& x1, double thickness) {
  const FaceArray& faces = mesh.faces();
  const EdgeArray& edges = mesh.edges();
  const auto grow = [&](const Aabb& box) {
    return thickness > 0 ? grown_outwards(box, 0.5 * thickness) : box;
  };
  std::vector<Aabb> face_boxes(static_cast<std::size_t>(mesh.num_faces()));
  swept_face_boxes(faces, x0, x1, face_boxes);
  for (Aabb& box : face_boxes) box = grow(box);
  std::vector<Aabb> edge_boxes(static_cast<std::size_t>(mesh.num_edges()));
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    edge_boxes[e] = grow(swept_box(x0, x1, {edges(e, 0), edges(e, 1)}));
  }
  const SortedBoxes sorted_faces(std::move(face_boxes));
  const SortedBoxes sorted_edges(edge_boxes);

  tbb::enumerable_thread_specific<std::vector<VertexFacePair>> vf_pairs;
  tbb::enumerable_thread_specific<std::vector<EdgeEdgePair>> ee_pairs;
  tbb::parallel_for(Index{0}, mesh.num_vertices(), [&](Index v) {
    if (mesh.vertex_faces(v).empty()) return;
    auto& out = vf_pairs.local();
    sorted_faces.for_each_overlapping(grow(swept_box(x0, x1, {v})), [&](Index f) {
      if (faces(f, 0) != v && faces(f, 1) != v && faces(f, 2) != v) out.push_back({v, f});
    });
  });
  tbb::parallel_for(Index{0}, mesh.num_edges(), [&](Index e1) {
    auto& out = ee_pairs.local();
    sorted_edges.for_each_overlapping(edge_boxes[e1], [&](Index e2) {
      if (e2 <= e1) return;
      const bool share = edges(e1, 0) == edges(e2, 0) || edges(e1, 0) == edges(e2, 1) ||
                         edges(e1, 1) == edges(e2, 0) || edges(e1, 1) == edges(e2, 1);
      if (!share) out.push_back({e1, e2});
    });
  });
  std::vector<VertexFacePair> all_vf;
  for (auto& v : vf_pairs) all_vf.insert(all_vf.end(), v.begin(), v.end());
  std::vector<EdgeEdgePair> all_ee;
  for (auto& v : ee_pairs) all_ee.insert(all_ee.end(), v.begin(), v.end());
  return test_pairs_exactly(mesh, x0, x1, {all_vf, all_ee}, thickness);
}

}  // namespace tailor

/// @file
/// Three BVHs (vertices, edges, faces) and their overlapping pairs.

#include "tailor/detection/feature_box_pairs.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>

#include "tailor/bvh/feature_boxes.hpp"

namespace tailor {

bool face_holds(const TriangleMesh& mesh, Index f, Index v) {
  const auto face = mesh.faces().row(f);
  return face[0] == v || face[1] == v || face[2] == v;
}

bool edges_share_an_end(const TriangleMesh& mesh, Index e, Index g) {
  const auto a = mesh.edges().row(e), b = mesh.edges().row(g);
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

template <class Box>
void BasicFeatureBoxTrees<Box>::update(const TriangleMesh& mesh,
                                       const std::vector<Box>& vertex_boxes) {
  // Not kept between updates: kept, they saved 0.4 ms of the funnel's refit and cost 11 MB
  // at cloth-ball's peak.
  std::vector<Box> edges(static_cast<std::size_t>(mesh.num_edges()));
  std::vector<Box> faces(static_cast<std::size_t>(mesh.num_faces()));
  bound_edges_and_faces(mesh, vertex_boxes, edges, faces);
  // A tree is built once (the number of primitives tells), refitted afterwards.
  const auto set = [](BasicBvh<Box>& tree, const std::vector<Box>& boxes) {
    if (tree.num_primitives() == static_cast<Index>(boxes.size()) && !boxes.empty()) {
      tree.refit(boxes);
    } else {
      tree = BasicBvh<Box>(boxes);
    }
  };
  tbb::parallel_invoke([&] { set(m_vertices, vertex_boxes); }, [&] { set(m_edges, edges); },
                       [&] { set(m_faces, faces); });
}

template <class Box>
std::vector<FeaturePairs> BasicFeatureBoxTrees<Box>::overlapping_pair_parts(
    const TriangleMesh& mesh) const {
  // Each thread collects its pairs.
  tbb::enumerable_thread_specific<FeaturePairs> found;
  const auto local = [&]() -> FeaturePairs& { return found.local(); };
  m_vertices.parallel_for_each_overlapping_pair(m_faces, local,
                                                [&](FeaturePairs& sink, Index v, Index f) {
                                                  if (!face_holds(mesh, f, v))
                                                    sink.vertex_face.push_back({v, f});
                                                });
  m_edges.parallel_for_each_self_overlapping_pair(local, [&](FeaturePairs& sink, Index e, Index g) {
    if (!edges_share_an_end(mesh, e, g)) sink.edge_edge.push_back({std::min(e, g), std::max(e, g)});
  });
  std::vector<FeaturePairs> parts;
  for (FeaturePairs& part : found) parts.push_back(std::move(part));
  return parts;
}

template <class Box>
FeaturePairs BasicFeatureBoxTrees<Box>::overlapping_pairs(const TriangleMesh& mesh) const {
  std::vector<FeaturePairs> parts = overlapping_pair_parts(mesh);
  FeaturePairs pairs;
  for (FeaturePairs& part : parts) {
    pairs.vertex_face.insert(pairs.vertex_face.end(), part.vertex_face.begin(),
                             part.vertex_face.end());
    pairs.edge_edge.insert(pairs.edge_edge.end(), part.edge_edge.begin(), part.edge_edge.end());
    part = {};  // freed as it is copied
  }
  return pairs;
}

template class BasicFeatureBoxTrees<StepBox>;

}  // namespace tailor

#include "tailor/detection/exact_pair_tests.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "tailor/ccd/ccd.hpp"

namespace tailor {
namespace {

struct ThreadOutput {
  CollisionSet collisions;
  std::int64_t exact = 0;
};

EdgeEdgeCollision make_edge_edge(const EdgeArray& edges, Index e1, Index e2, double toi) {
  // Edges are stored (a, b) with a < b; order the two edges by their vertex ids.
  if (std::pair(edges(e2, 0), edges(e2, 1)) < std::pair(edges(e1, 0), edges(e1, 1))) {
    std::swap(e1, e2);
  }
  return {edges(e1, 0), edges(e1, 1), edges(e2, 0), edges(e2, 1), e1, e2, toi};
}

template <class T>
void sort_unique(std::vector<T>& items) {
  std::sort(items.begin(), items.end());
  items.erase(std::unique(items.begin(), items.end(),
                          [](const T& a, const T& b) { return !(a < b) && !(b < a); }),
              items.end());
}

}  // namespace

CollisionSet test_pairs_exactly(const TriangleMesh& mesh, const Positions& x0, const Positions& x1,
                                std::span<const VertexFacePair> vertex_face,
                                std::span<const EdgeEdgePair> edge_edge,
                                std::int64_t* exact_fallbacks) {
  const FaceArray& faces = mesh.faces();
  const EdgeArray& edges = mesh.edges();
  tbb::enumerable_thread_specific<ThreadOutput> outputs;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, vertex_face.size(), 256), [&](const auto& range) {
        ThreadOutput& out = outputs.local();
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
          const auto [v, f] = vertex_face[i];
          const Index a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
          const CcdResult result = vertex_face_ccd({x0.row(v), x0.row(a), x0.row(b), x0.row(c),
                                                    x1.row(v), x1.row(a), x1.row(b), x1.row(c)});
          out.exact += result.path == CcdPath::exact || result.path == CcdPath::gmp;
          if (result.hit) out.collisions.vertex_face.push_back({v, f, result.toi});
        }
      });
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, edge_edge.size(), 256), [&](const auto& range) {
        ThreadOutput& out = outputs.local();
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
          const auto [e1, e2] = edge_edge[i];
          const Index a = edges(e1, 0), b = edges(e1, 1);
          const Index c = edges(e2, 0), d = edges(e2, 1);
          const CcdResult result = edge_edge_ccd({x0.row(a), x0.row(b), x0.row(c), x0.row(d),
                                                  x1.row(a), x1.row(b), x1.row(c), x1.row(d)});
          out.exact += result.path == CcdPath::exact || result.path == CcdPath::gmp;
          if (result.hit) {
            out.collisions.edge_edge.push_back(make_edge_edge(edges, e1, e2, result.toi));
          }
        }
      });
  CollisionSet all;
  std::int64_t exact = 0;
  for (ThreadOutput& out : outputs) {
    all.vertex_face.insert(all.vertex_face.end(), out.collisions.vertex_face.begin(),
                           out.collisions.vertex_face.end());
    all.edge_edge.insert(all.edge_edge.end(), out.collisions.edge_edge.begin(),
                         out.collisions.edge_edge.end());
    exact += out.exact;
  }
  sort_unique(all.vertex_face);
  sort_unique(all.edge_edge);
  if (exact_fallbacks != nullptr) *exact_fallbacks = exact;
  return all;
}

}  // namespace tailor

#include "tailor/candidates/isolated_set.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace tailor {
namespace {

bool face_has_vertex(const TriangleMesh& mesh, Index f, Index v) {
  const auto face = mesh.faces().row(f);
  return face[0] == v || face[1] == v || face[2] == v;
}

// Faces sharing a vertex with face `f` (`f` included), sorted, unique.
void faces_near(const TriangleMesh& mesh, Index f, std::vector<Index>& out) {
  out.clear();
  for (int k = 0; k < 3; ++k) {
    for (Index g : mesh.vertex_faces(mesh.faces()(f, k))) out.push_back(g);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// Runs `body(i, out)` for i in [0, n) in parallel blocks and concatenates the outputs
// in index order, so the result does not depend on scheduling.
template <class T, class Body>
std::vector<T> collect_in_order(Index n, Body body) {
  constexpr Index kBlock = 1024;
  const Index num_blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::vector<T>> blocks(static_cast<std::size_t>(num_blocks));
  tbb::parallel_for(Index{0}, num_blocks, [&](Index b) {
    std::vector<Index> scratch;
    for (Index i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      body(i, blocks[static_cast<std::size_t>(b)], scratch);
    }
  });
  std::vector<T> all;
  for (auto& block : blocks) all.insert(all.end(), block.begin(), block.end());
  return all;
}

}  // namespace

Index first_face_disjoint_from(const TriangleMesh& mesh, Index v, Index g) {
  for (Index f : mesh.vertex_faces(v)) {
    if (!mesh.faces_share_vertex(f, g)) return f;
  }
  return -1;
}

std::pair<Index, Index> first_disjoint_face_pair(const TriangleMesh& mesh, Index e1, Index e2) {
  for (Index f1 : mesh.edge_faces(e1)) {
    for (Index f2 : mesh.edge_faces(e2)) {
      if (!mesh.faces_share_vertex(f1, f2)) return {f1, f2};
    }
  }
  return {-1, -1};
}

IsolatedSet IsolatedSet::build(const TriangleMesh& mesh) {
  IsolatedSet set;
  // An orphan face g shares a vertex with every face around v, in particular with the
  // first, so the faces near that one are all the candidates.
  set.vertex_face = collect_in_order<VertexFacePair>(
      mesh.num_vertices(),
      [&](Index v, std::vector<VertexFacePair>& out, std::vector<Index>& near) {
        const auto around = mesh.vertex_faces(v);
        if (around.empty()) return;  // unreferenced vertices are not part of the surface
        faces_near(mesh, around[0], near);
        for (Index g : near) {
          if (!face_has_vertex(mesh, g, v) && first_face_disjoint_from(mesh, v, g) < 0) {
            out.push_back({v, g});
          }
        }
      });
  set.edge_edge = collect_in_order<EdgeEdgePair>(
      mesh.num_edges(), [&](Index e1, std::vector<EdgeEdgePair>& out, std::vector<Index>& near) {
        // Every face of an orphan partner e2 shares a vertex with the first face of e1, so
        // e2 is an edge of a face near that one.
        faces_near(mesh, mesh.edge_faces(e1)[0], near);
        std::vector<Index> candidates;
        for (Index g : near) {
          for (Index e2 : mesh.face_edges(g)) {
            if (e2 > e1 && !mesh.edges_share_vertex(e1, e2)) candidates.push_back(e2);
          }
        }
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (Index e2 : candidates) {
          if (first_disjoint_face_pair(mesh, e1, e2).first < 0) out.push_back({e1, e2});
        }
      });
  return set;
}

}  // namespace tailor

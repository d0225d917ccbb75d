#include "tailor/candidates/isolated_set.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <span>

namespace tailor {
namespace {

using Corners = std::array<Index, 3>;

Corners corners_of(const TriangleMesh& mesh, Index f) {
  const auto face = mesh.faces().row(f);
  return {face[0], face[1], face[2]};
}

bool has_vertex(const Corners& face, Index v) {
  return face[0] == v || face[1] == v || face[2] == v;
}

bool share_vertex(const Corners& a, const Corners& b) {
  return has_vertex(b, a[0]) || has_vertex(b, a[1]) || has_vertex(b, a[2]);
}

// True when every face of `faces` shares a vertex with every face around `corners`.
bool all_share_vertex(const TriangleMesh& mesh, std::span<const Index> faces,
                      std::span<const Corners> around) {
  for (Index f : faces) {
    const Corners c = corners_of(mesh, f);
    for (const Corners& a : around) {
      if (!share_vertex(c, a)) return false;
    }
  }
  return true;
}

// Per-thread work space, reused from one vertex or edge to the next.
struct Scratch {
  std::vector<Index> near, candidates;
  std::vector<Corners> around;
};

// Faces sharing a vertex with face `f` (`f` included), sorted, unique.
void faces_near(const TriangleMesh& mesh, Index f, std::vector<Index>& out) {
  out.clear();
  for (int k = 0; k < 3; ++k) {
    for (Index g : mesh.vertex_faces(mesh.faces()(f, k))) out.push_back(g);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void sort_unique(std::vector<Index>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

// Runs `body(i, out, scratch)` for i in [0, n) in parallel blocks and concatenates the
// outputs in index order, so the result does not depend on scheduling.
template <class T, class Body>
std::vector<T> collect_in_order(Index n, Body body) {
  constexpr Index kBlock = 1024;
  const Index num_blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::vector<T>> blocks(static_cast<std::size_t>(num_blocks));
  tbb::parallel_for(Index{0}, num_blocks, [&](Index b) {
    Scratch scratch;
    for (Index i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      body(i, blocks[static_cast<std::size_t>(b)], scratch);
    }
  });
  std::vector<T> all;
  for (auto& block : blocks) all.insert(all.end(), block.begin(), block.end());
  return all;
}

// Orphan faces g of vertex v, in increasing order.
void add_vertex_orphans(const TriangleMesh& mesh, Index v, std::vector<VertexFacePair>& out,
                        Scratch& scratch) {
  const auto around = mesh.vertex_faces(v);
  if (around.empty()) return;  // unreferenced vertices are not part of the surface
  // An orphan face g shares a vertex with every face around v, in particular with the
  // first, so the faces near that one are all the candidates.
  faces_near(mesh, around[0], scratch.near);
  scratch.around.clear();
  for (Index f : around) scratch.around.push_back(corners_of(mesh, f));
  for (Index g : scratch.near) {
    const Index one[1] = {g};
    if (!has_vertex(corners_of(mesh, g), v) && all_share_vertex(mesh, one, scratch.around)) {
      out.push_back({v, g});
    }
  }
}

// Orphan partners e2 > e1 of edge e1, in increasing order.
void add_edge_orphans(const TriangleMesh& mesh, Index e1, std::vector<EdgeEdgePair>& out,
                      Scratch& scratch) {
  const auto faces1 = mesh.edge_faces(e1);
  // Every face of an orphan partner e2 shares a vertex with the first face of e1, so e2
  // is an edge of a face near that one.
  faces_near(mesh, faces1[0], scratch.near);
  scratch.candidates.clear();
  for (Index g : scratch.near) {
    for (Index e2 : mesh.face_edges(g)) {
      if (e2 > e1 && !mesh.edges_share_vertex(e1, e2)) scratch.candidates.push_back(e2);
    }
  }
  sort_unique(scratch.candidates);
  scratch.around.clear();
  for (Index f : faces1) scratch.around.push_back(corners_of(mesh, f));
  for (Index e2 : scratch.candidates) {
    if (all_share_vertex(mesh, mesh.edge_faces(e2), scratch.around)) out.push_back({e1, e2});
  }
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
  set.vertex_face = collect_in_order<VertexFacePair>(
      mesh.num_vertices(), [&](Index v, std::vector<VertexFacePair>& out, Scratch& scratch) {
        add_vertex_orphans(mesh, v, out, scratch);
      });
  set.edge_edge = collect_in_order<EdgeEdgePair>(
      mesh.num_edges(), [&](Index e1, std::vector<EdgeEdgePair>& out, Scratch& scratch) {
        add_edge_orphans(mesh, e1, out, scratch);
      });
  return set;
}

}  // namespace tailor

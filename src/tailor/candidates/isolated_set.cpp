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

// True when the face with `corners` shares a vertex with every face of `around`.
bool all_share_vertex(const Corners& corners, std::span<const Corners> around) {
  for (const Corners& a : around) {
    if (!share_vertex(corners, a)) return false;
  }
  return true;
}

// Per-thread work space, reused from one vertex or edge to the next.
struct Scratch {
  std::vector<Index> near, candidates;
  std::vector<Corners> around;
};

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

// Appends the found partners of one feature in increasing order, once each (a partner
// can be reached from two candidate faces).
template <class Pair>
void append_sorted(std::vector<Index>& found, Index feature, std::vector<Pair>& out) {
  sort_unique(found);
  for (Index partner : found) out.push_back({feature, partner});
}

// Orphan faces g of vertex v, in increasing order.
void add_vertex_orphans(const TriangleMesh& mesh, Index v, std::vector<VertexFacePair>& out,
                        Scratch& scratch) {
  const auto around = mesh.vertex_faces(v);
  if (around.empty()) return;  // unreferenced vertices are not part of the surface
  scratch.around.clear();
  for (Index f : around) scratch.around.push_back(corners_of(mesh, f));
  // An orphan face g (v not in g) shares a vertex with the first face around v, (v, x, y),
  // so it is a face around x or around y.
  scratch.candidates.clear();
  for (Index w : scratch.around[0]) {
    if (w == v) continue;
    for (Index g : mesh.vertex_faces(w)) {
      const Corners corners = corners_of(mesh, g);
      if (!has_vertex(corners, v) && all_share_vertex(corners, scratch.around)) {
        scratch.candidates.push_back(g);
      }
    }
  }
  append_sorted(scratch.candidates, v, out);
}

// Orphan partners e2 > e1 of edge e1 = (a, b), in increasing order.
void add_edge_orphans(const TriangleMesh& mesh, Index e1, std::vector<EdgeEdgePair>& out,
                      Scratch& scratch) {
  const Index a = mesh.edges()(e1, 0), b = mesh.edges()(e1, 1);
  const auto faces1 = mesh.edge_faces(e1);
  scratch.around.clear();
  for (Index f : faces1) scratch.around.push_back(corners_of(mesh, f));
  // A face G of an orphan partner shares a vertex with every face (a, b, c_i) of e1: it
  // holds a, or b, or else every apex c_i. So G is a face around a, around b, or around
  // c_1 holding every other apex; e2 is an edge of G.
  scratch.candidates.clear();
  // `known`: a face of e2 already known to share a vertex with every face of e1.
  const auto try_partner = [&](Index e2, Index known) {
    for (Index g : mesh.edge_faces(e2)) {
      if (g != known && !all_share_vertex(corners_of(mesh, g), scratch.around)) return;
    }
    scratch.candidates.push_back(e2);
  };
  // Around a (b): the one edge of G away from a (b), edge (j + 1) of G when a is its
  // corner j, if it avoids the other end too.
  for (const Index end : {a, b}) {
    const Index other_end = end == a ? b : a;
    for (Index g : mesh.vertex_faces(end)) {
      const Corners corners = corners_of(mesh, g);
      const int j = corners[0] == end ? 0 : corners[1] == end ? 1 : 2;
      const Index e2 = mesh.face_edges(g)[(j + 1) % 3];
      if (e2 > e1 && corners[(j + 1) % 3] != other_end && corners[(j + 2) % 3] != other_end) {
        try_partner(e2, g);  // g holds `end`, a corner of every face of e1
      }
    }
  }
  const auto apex = [&](const Corners& face) {
    return face[0] != a && face[0] != b   ? face[0]
           : face[1] != a && face[1] != b ? face[1]
                                          : face[2];
  };
  for (Index g : mesh.vertex_faces(apex(scratch.around[0]))) {
    const Corners corners = corners_of(mesh, g);
    bool holds_every_apex = !has_vertex(corners, a) && !has_vertex(corners, b);
    for (const Corners& f : scratch.around) holds_every_apex &= has_vertex(corners, apex(f));
    if (!holds_every_apex) continue;  // faces around a or b are done above
    for (Index e2 : mesh.face_edges(g)) {
      if (e2 > e1) try_partner(e2, g);  // G avoids a and b, so its edges do; it holds every apex
    }
  }
  append_sorted(scratch.candidates, e1, out);
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

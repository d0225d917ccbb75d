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

// Face g seen from its corner v: g's other corners, the edge of g opposite v and the faces
// across that edge. Each vertex's faces and edges are read by every feature around it:
// gathered once, the enumeration below reads them in sequence.
struct LinkEntry {
  Index face;           // g
  Index opposite_edge;  // the edge of g that avoids v
  Index other[2];       // g's corners after v, in g's order
  Corners far;          // the face across opposite_edge, when far_faces is 1
  Index far_faces;      // faces of opposite_edge other than g (0: a boundary edge)
};

// Every vertex's link entries, in the order of its vertex_faces(), built in parallel.
class Links {
 public:
  explicit Links(const TriangleMesh& mesh) : m_offsets(mesh.num_vertices() + 1, 0) {
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
      m_offsets[v + 1] = m_offsets[v] + static_cast<Index>(mesh.vertex_faces(v).size());
    }
    m_entries.resize(static_cast<std::size_t>(m_offsets.back()));
    tbb::parallel_for(Index{0}, mesh.num_vertices(), [&](Index v) {
      Index slot = m_offsets[v];
      for (Index g : mesh.vertex_faces(v)) m_entries[slot++] = entry(mesh, v, g);
    });
  }
  std::span<const LinkEntry> of(Index v) const {
    return {m_entries.data() + m_offsets[v],
            static_cast<std::size_t>(m_offsets[v + 1] - m_offsets[v])};
  }

 private:
  static LinkEntry entry(const TriangleMesh& mesh, Index v, Index g) {
    const Corners corners = corners_of(mesh, g);
    const int j = corners[0] == v ? 0 : corners[1] == v ? 1 : 2;
    LinkEntry e{
        g, mesh.face_edges(g)[(j + 1) % 3], {corners[(j + 1) % 3], corners[(j + 2) % 3]}, {}, 0};
    const auto across = mesh.edge_faces(e.opposite_edge);
    e.far_faces = static_cast<Index>(across.size()) - 1;
    if (e.far_faces == 1) e.far = corners_of(mesh, across[0] == g ? across[1] : across[0]);
    return e;
  }

  std::vector<Index> m_offsets;
  std::vector<LinkEntry> m_entries;
};

// Each vertex's neighbours (the other ends of its edges), 8 bytes per edge: small enough to
// stay in cache where the link entries (32 bytes per face corner) do not.
class Neighbours {
 public:
  explicit Neighbours(const TriangleMesh& mesh) : m_offsets(mesh.num_vertices() + 1, 0) {
    const EdgeArray& edges = mesh.edges();
    for (Index e = 0; e < mesh.num_edges(); ++e) {
      ++m_offsets[edges(e, 0) + 1];
      ++m_offsets[edges(e, 1) + 1];
    }
    for (Index v = 0; v < mesh.num_vertices(); ++v) m_offsets[v + 1] += m_offsets[v];
    m_ids.resize(static_cast<std::size_t>(m_offsets.back()));
    std::vector<Index> next(m_offsets.begin(), m_offsets.end() - 1);
    for (Index e = 0; e < mesh.num_edges(); ++e) {
      m_ids[next[edges(e, 0)]++] = edges(e, 1);
      m_ids[next[edges(e, 1)]++] = edges(e, 0);
    }
  }
  std::span<const Index> of(Index v) const {
    return {m_ids.data() + m_offsets[v], static_cast<std::size_t>(m_offsets[v + 1] - m_offsets[v])};
  }
  bool adjacent(Index u, Index v) const {
    bool found = false;
    for (Index w : of(u)) found |= w == v;
    return found;
  }

 private:
  std::vector<Index> m_offsets, m_ids;
};

// Vertices whose every face's opposite edge has exactly one other face, which does not hold
// the vertex (no boundary, non-manifold or doubled face across from it).
std::vector<char> plain_vertices(const TriangleMesh& mesh, const Links& links) {
  std::vector<char> plain(static_cast<std::size_t>(mesh.num_vertices()));
  tbb::parallel_for(Index{0}, mesh.num_vertices(), [&](Index v) {
    bool all = true;
    for (const LinkEntry& l : links.of(v)) all &= l.far_faces == 1 && !has_vertex(l.far, v);
    plain[v] = all;
  });
  return plain;
}

// Whether edge e1 = (a, b) certainly has no orphan partner, from data that stays in cache.
// Why it holds: let e1's faces be (a, b, c1) and (a, b, c2) and e2 = (p, q) avoid a and b.
// A face G of e2 that holds neither a nor b shares a vertex with both faces of e1 only if it
// holds c1 and c2, which are then adjacent. Otherwise every face of e2 holds a or b. If e2
// has one face, or several holding the same one of them, that vertex is not plain (e2 is a
// boundary or non-manifold edge across from it, or its faces repeat). So e2's faces are (p, q,
// a) and (p, q, b): p and q are common neighbours of a and b; one of them is neither c1 nor
// c2 (both would make c1 and c2 adjacent). Hence no partner exists when e1 has two faces with
// distinct apexes that are not adjacent, a and b are plain, and a and b have no common
// neighbour but c1 and c2.
bool certainly_no_edge_orphans(const TriangleMesh& mesh, const Links& links,
                               const Neighbours& neighbours, const std::vector<char>& plain,
                               Index e1) {
  const Index a = mesh.edges()(e1, 0), b = mesh.edges()(e1, 1);
  if (!plain[a] || !plain[b]) return false;
  // e1's faces and their apexes from b's link (in cache: edges come sorted by b).
  Index apexes[2];
  int faces = 0;
  for (const LinkEntry& l : links.of(b)) {
    const bool holds_a = l.other[0] == a || l.other[1] == a;
    if (holds_a && faces < 2) apexes[faces] = l.other[0] == a ? l.other[1] : l.other[0];
    faces += holds_a;
  }
  if (faces != 2) return false;
  const Index c1 = apexes[0], c2 = apexes[1];
  if (c1 == c2 || neighbours.adjacent(c1, c2)) return false;
  bool other_common = false;
  for (Index x : neighbours.of(a)) {
    if (x != c1 && x != c2) other_common |= neighbours.adjacent(b, x);
  }
  return !other_common;
}

// Per-thread work space, reused from one vertex or edge to the next.
struct Scratch {
  std::vector<Index> candidates;
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
void add_vertex_orphans(const Links& links, Index v, std::vector<VertexFacePair>& out,
                        Scratch& scratch) {
  const auto around = links.of(v);
  if (around.empty()) return;  // unreferenced vertices are not part of the surface
  scratch.around.clear();
  for (const LinkEntry& l : around) scratch.around.push_back({v, l.other[0], l.other[1]});
  // An orphan face g (v not in g) shares a vertex with the first face around v, (v, x, y),
  // so it is a face around x or around y.
  scratch.candidates.clear();
  for (const Index w : around[0].other) {
    for (const LinkEntry& l : links.of(w)) {
      const Corners corners{w, l.other[0], l.other[1]};
      if (!has_vertex(corners, v) && all_share_vertex(corners, scratch.around)) {
        scratch.candidates.push_back(l.face);
      }
    }
  }
  append_sorted(scratch.candidates, v, out);
}

// Orphan partners e2 > e1 of edge e1 = (a, b), in increasing order.
void add_edge_orphans(const TriangleMesh& mesh, const Links& links, Index e1,
                      std::vector<EdgeEdgePair>& out, Scratch& scratch) {
  const Index a = mesh.edges()(e1, 0), b = mesh.edges()(e1, 1);
  // e1's faces are b's faces that hold a (edges come sorted by b: b's entries stay in
  // cache from one edge to the next).
  scratch.around.clear();
  for (const LinkEntry& l : links.of(b)) {
    if (l.other[0] == a || l.other[1] == a) scratch.around.push_back({b, l.other[0], l.other[1]});
  }
  // A face G of an orphan partner shares a vertex with every face (a, b, c_i) of e1: it
  // holds a, or b, or else every apex c_i. So G is a face around a, around b, or around
  // c_1 holding every other apex; e2 is an edge of G.
  scratch.candidates.clear();
  // Whether every face of e2 but `known` (which does) shares a vertex with every face of e1.
  const auto others_touch = [&](Index e2, Index known) {
    for (Index g : mesh.edge_faces(e2)) {
      if (g != known && !all_share_vertex(corners_of(mesh, g), scratch.around)) return false;
    }
    return true;
  };
  // Around a (b): the edge of G opposite a (b), if it avoids the other end too. G holds a
  // (b), a corner of every face of e1; so do the faces across e2, or they must touch.
  for (const Index end : {a, b}) {
    const Index other_end = end == a ? b : a;
    for (const LinkEntry& l : links.of(end)) {
      if (l.opposite_edge <= e1 || l.other[0] == other_end || l.other[1] == other_end) continue;
      const bool touch =
          l.far_faces == 0 || (l.far_faces == 1 ? all_share_vertex(l.far, scratch.around)
                                                : others_touch(l.opposite_edge, l.face));
      if (touch) scratch.candidates.push_back(l.opposite_edge);
    }
  }
  const auto apex = [&](const Corners& face) {
    return face[0] != a && face[0] != b   ? face[0]
           : face[1] != a && face[1] != b ? face[1]
                                          : face[2];
  };
  const Index first_apex = apex(scratch.around[0]);
  for (const LinkEntry& l : links.of(first_apex)) {
    const Corners corners{first_apex, l.other[0], l.other[1]};
    bool holds_every_apex = !has_vertex(corners, a) && !has_vertex(corners, b);
    for (const Corners& f : scratch.around) holds_every_apex &= has_vertex(corners, apex(f));
    if (!holds_every_apex) continue;  // faces around a or b are done above
    for (Index e2 : mesh.face_edges(l.face)) {
      // G avoids a and b, so its edges do; G holds every apex.
      if (e2 > e1 && others_touch(e2, l.face)) scratch.candidates.push_back(e2);
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
  const Links links(mesh);
  IsolatedSet set;
  set.vertex_face = collect_in_order<VertexFacePair>(
      mesh.num_vertices(), [&](Index v, std::vector<VertexFacePair>& out, Scratch& scratch) {
        add_vertex_orphans(links, v, out, scratch);
      });
  const Neighbours neighbours(mesh);
  const std::vector<char> plain = plain_vertices(mesh, links);
  set.edge_edge = collect_in_order<EdgeEdgePair>(
      mesh.num_edges(), [&](Index e1, std::vector<EdgeEdgePair>& out, Scratch& scratch) {
        if (!certainly_no_edge_orphans(mesh, links, neighbours, plain, e1)) {
          add_edge_orphans(mesh, links, e1, out, scratch);
        }
      });
  return set;
}

}  // namespace tailor

/// @file
/// Connectivity of a triangle mesh, built with counting sorts (linear time).

#include "tailor/mesh/triangle_mesh.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>

#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

/// Turns per-bucket counts (size n+1, counts in [1..n]) into CSR offsets in place.
void counts_to_offsets(std::vector<Index>& offsets) {
  for (std::size_t i = 1; i < offsets.size(); ++i) offsets[i] += offsets[i - 1];
}

/// Union-find root with path halving.
Index find_root(std::vector<Index>& parent, Index v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace

TriangleMesh::TriangleMesh(Index num_vertices, FaceArray faces)
    : m_num_vertices(num_vertices), m_faces(std::move(faces)) {
  validate_faces();  // errors first, so nothing below sees a bad index
  // The edges and the vertices' faces do not depend on each other.
  tbb::parallel_invoke(
      [&] {
        build_edges(sorted_sides());
        build_edge_ends();
      },
      [&] {
        build_vertex_faces();
        label_components();
      });
  record_warnings();
  build_boundary_loops();
}

void TriangleMesh::validate_faces() const {
  if (m_num_vertices < 0) {
    throw InputError(fmt::format("mesh has a negative vertex count ({})", m_num_vertices));
  }
  if (m_faces.rows() > std::numeric_limits<Index>::max() / 3) {
    throw InputError(fmt::format("mesh has too many faces ({})", m_faces.rows()));
  }
  const Index nv = m_num_vertices;
  for (Index f = 0; f < num_faces(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const Index v = m_faces(f, i);
      if (v < 0 || v >= nv) {
        throw InputError(fmt::format(
            "face {} has vertex index {} out of range (mesh has {} vertices)", f, v, nv));
      }
    }
    if (m_faces(f, 0) == m_faces(f, 1) || m_faces(f, 1) == m_faces(f, 2) ||
        m_faces(f, 0) == m_faces(f, 2)) {
      throw InputError(fmt::format("face {} repeats a vertex ({} {} {})", f, m_faces(f, 0),
                                   m_faces(f, 1), m_faces(f, 2)));
    }
  }
}

TriangleMesh::SortedSides TriangleMesh::sorted_sides() const {
  // Bucket the 3F face sides by their larger vertex, then order each (small) bucket by the
  // smaller vertex. Slots of one side are s = 3f + i.
  const Index nf = num_faces(), nv = m_num_vertices;
  SortedSides sides;
  sides.bucket_offsets.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (Index f = 0; f < nf; ++f) {
    for (int i = 0; i < 3; ++i) {
      const Index b = std::max(m_faces(f, i), m_faces(f, (i + 1) % 3));
      ++sides.bucket_offsets[b + 1];
    }
  }
  counts_to_offsets(sides.bucket_offsets);
  // keys[k] = (smaller vertex << 32) | slot: sorting a bucket's keys orders it by the
  // smaller vertex, then by slot (hence by face), with contiguous memory access only.
  sides.keys.resize(3 * static_cast<std::size_t>(nf));
  std::vector<Index> cursor(sides.bucket_offsets.begin(), sides.bucket_offsets.end() - 1);
  for (Index f = 0; f < nf; ++f) {
    for (int i = 0; i < 3; ++i) {
      const Index u = m_faces(f, i), w = m_faces(f, (i + 1) % 3);
      const auto lo = static_cast<std::uint64_t>(std::min(u, w));
      sides.keys[cursor[std::max(u, w)]++] = (lo << 32) | static_cast<std::uint64_t>(3 * f + i);
    }
  }
  for (Index b = 0; b < nv; ++b) {
    const auto first = sides.keys.begin() + sides.bucket_offsets[b];
    const auto last = sides.keys.begin() + sides.bucket_offsets[b + 1];
    if (last - first > 32) {
      std::sort(first, last);
    } else {
      // Buckets hold ~6 sides on average: insertion sort, allocation-free.
      for (auto it = first + (last > first ? 1 : 0); it < last; ++it) {
        const std::uint64_t key = *it;
        auto hole = it;
        while (hole > first && key < *(hole - 1)) {
          *hole = *(hole - 1);
          --hole;
        }
        *hole = key;
      }
    }
  }
  return sides;
}

void TriangleMesh::build_edges(const SortedSides& sides) {
  const std::size_t num_slots = sides.keys.size();
  m_face_edges.assign(num_slots, -1);
  m_edge_face_ids.resize(num_slots);
  m_edge_face_offsets.clear();
  m_edge_face_offsets.reserve(num_slots / 2 + 2);
  std::vector<Index> edge_a, edge_b;
  edge_a.reserve(num_slots / 2 + 1);
  edge_b.reserve(num_slots / 2 + 1);
  for (Index b = 0; b < m_num_vertices; ++b) {
    Index prev_a = -1;
    for (Index k = sides.bucket_offsets[b]; k < sides.bucket_offsets[b + 1]; ++k) {
      const Index a = static_cast<Index>(sides.keys[k] >> 32);
      const Index slot = static_cast<Index>(sides.keys[k] & 0xffffffffu);
      if (a != prev_a) {
        m_edge_face_offsets.push_back(k);
        edge_a.push_back(a);
        edge_b.push_back(b);
        prev_a = a;
      }
      m_face_edges[slot] = static_cast<Index>(edge_a.size()) - 1;
      m_edge_face_ids[k] = slot / 3;
    }
  }
  m_edge_face_offsets.push_back(static_cast<Index>(num_slots));
  const Index ne = static_cast<Index>(edge_a.size());
  m_edges.resize(ne, 2);
  for (Index e = 0; e < ne; ++e) {
    m_edges(e, 0) = edge_a[e];
    m_edges(e, 1) = edge_b[e];
  }
}

void TriangleMesh::build_vertex_faces() {
  // Faces visited in order, so each list is increasing.
  m_vertex_face_offsets.assign(static_cast<std::size_t>(m_num_vertices) + 1, 0);
  for (Index f = 0; f < num_faces(); ++f) {
    for (int i = 0; i < 3; ++i) ++m_vertex_face_offsets[m_faces(f, i) + 1];
  }
  counts_to_offsets(m_vertex_face_offsets);
  m_vertex_face_ids.resize(3 * static_cast<std::size_t>(num_faces()));
  std::vector<Index> cursor(m_vertex_face_offsets.begin(), m_vertex_face_offsets.end() - 1);
  for (Index f = 0; f < num_faces(); ++f) {
    for (int i = 0; i < 3; ++i) m_vertex_face_ids[cursor[m_faces(f, i)]++] = f;
  }
}

void TriangleMesh::build_edge_ends() {
  // Edges are sorted by (b, a), so the edges (a, b) of one b are a contiguous, a-sorted
  // range. (A full vertex -> edges table took 14 bytes per triangle, which the detector
  // never reads; vertex_edges() assembles a list.)
  m_edge_end_offsets.assign(static_cast<std::size_t>(m_num_vertices) + 1, 0);
  for (Index e = 0; e < num_edges(); ++e) ++m_edge_end_offsets[m_edges(e, 1) + 1];
  counts_to_offsets(m_edge_end_offsets);
}

void TriangleMesh::record_warnings() {
  for (Index e = 0; e < num_edges(); ++e) {
    if (m_edge_face_offsets[e + 1] - m_edge_face_offsets[e] > 2) {
      m_validation.non_manifold_edges.push_back(e);
    }
  }
  for (Index v = 0; v < m_num_vertices; ++v) {
    if (m_vertex_face_offsets[v + 1] == m_vertex_face_offsets[v]) {
      m_validation.unreferenced_vertices.push_back(v);
    }
  }
  if (!m_validation.non_manifold_edges.empty()) {
    const Index e = m_validation.non_manifold_edges.front();
    spdlog::warn("mesh has {} non-manifold edges (more than two faces), e.g. edge {} ({}, {})",
                 m_validation.non_manifold_edges.size(), e, m_edges(e, 0), m_edges(e, 1));
  }
  if (!m_validation.unreferenced_vertices.empty()) {
    spdlog::warn("mesh has {} vertices used by no face, e.g. vertex {}",
                 m_validation.unreferenced_vertices.size(),
                 m_validation.unreferenced_vertices.front());
  }
}

TriangleMesh::BoundaryEdges TriangleMesh::boundary_edges() const {
  // Each boundary edge carries the direction of its face's side, and every vertex lists
  // its boundary edges (CSR).
  const Index ne = num_edges();
  BoundaryEdges boundary{std::vector<Index>(ne, -1),
                         std::vector<Index>(ne, -1),
                         std::vector<Index>(static_cast<std::size_t>(m_num_vertices) + 1, 0),
                         {}};
  for (Index e = 0; e < ne; ++e) {
    if (m_edge_face_offsets[e + 1] - m_edge_face_offsets[e] != 1) continue;
    const Index f = m_edge_face_ids[m_edge_face_offsets[e]];
    for (int i = 0; i < 3; ++i) {
      if (m_face_edges[3 * f + i] == e) {
        boundary.from[e] = m_faces(f, i);
        boundary.to[e] = m_faces(f, (i + 1) % 3);
      }
    }
    ++boundary.vertex_offsets[m_edges(e, 0) + 1];
    ++boundary.vertex_offsets[m_edges(e, 1) + 1];
  }
  counts_to_offsets(boundary.vertex_offsets);
  boundary.vertex_edges.resize(static_cast<std::size_t>(boundary.vertex_offsets.back()));
  std::vector<Index> cursor(boundary.vertex_offsets.begin(), boundary.vertex_offsets.end() - 1);
  for (Index e = 0; e < ne; ++e) {
    if (boundary.from[e] < 0) continue;
    boundary.vertex_edges[cursor[m_edges(e, 0)]++] = e;
    boundary.vertex_edges[cursor[m_edges(e, 1)]++] = e;
  }
  return boundary;
}

void TriangleMesh::build_boundary_loops() {
  // The walk prefers continuing along each boundary edge's direction but accepts any
  // unused boundary edge at the current vertex, so inconsistent orientations and pinched
  // (non-manifold) vertices still terminate: every boundary edge is consumed exactly once.
  const BoundaryEdges boundary = boundary_edges();
  if (boundary.vertex_edges.empty()) return;
  const Index ne = num_edges();
  std::vector<char> used(ne, 0);
  // Next unused boundary edge at `v`, preferring one that leaves `v` (forward walk) or
  // arrives at `v` (backward walk) along its face's orientation; -1 if none is left.
  auto pick = [&](Index v, bool forward) {
    Index chosen = -1;
    for (Index k = boundary.vertex_offsets[v]; k < boundary.vertex_offsets[v + 1]; ++k) {
      const Index e = boundary.vertex_edges[k];
      if (used[e]) continue;
      if ((forward ? boundary.from[e] : boundary.to[e]) == v) return e;
      if (chosen < 0) chosen = e;
    }
    return chosen;
  };
  auto other_end = [&](Index e, Index v) {
    return m_edges(e, 0) == v ? m_edges(e, 1) : m_edges(e, 0);
  };
  std::vector<Index> backward;
  m_loop_vertices.reserve(boundary.vertex_edges.size() / 2);
  for (Index start_edge = 0; start_edge < ne; ++start_edge) {
    if (boundary.from[start_edge] < 0 || used[start_edge]) continue;
    used[start_edge] = 1;
    const Index start = boundary.from[start_edge];
    const std::size_t loop_begin = m_loop_vertices.size();
    m_loop_vertices.push_back(start);
    Index current = boundary.to[start_edge];
    bool closed = false;
    for (;;) {
      if (current == start) {
        closed = true;
        break;
      }
      m_loop_vertices.push_back(current);
      const Index e = pick(current, true);
      if (e < 0) break;
      used[e] = 1;
      current = other_end(e, current);
    }
    if (!closed) {
      // An open chain (pinched or inconsistently oriented boundary): extend it backwards
      // from its start so that it is as long as possible.
      backward.clear();
      Index back = start;
      for (Index e = pick(back, false); e >= 0; e = pick(back, false)) {
        used[e] = 1;
        back = other_end(e, back);
        if (back == current) break;  // reached the chain's other end: now closed
        backward.push_back(back);
      }
      m_loop_vertices.insert(m_loop_vertices.begin() + static_cast<std::ptrdiff_t>(loop_begin),
                             backward.rbegin(), backward.rend());
    }
    m_loop_offsets.push_back(static_cast<Index>(m_loop_vertices.size()));
  }
}

void TriangleMesh::label_components() {
  // Faces joined by shared vertices.
  const Index nf = num_faces(), nv = m_num_vertices;
  std::vector<Index> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  for (Index f = 0; f < nf; ++f) {
    const Index r0 = find_root(parent, m_faces(f, 0));
    for (int i = 1; i < 3; ++i) {
      const Index r = find_root(parent, m_faces(f, i));
      if (r != r0) parent[r] = r0;
    }
  }
  std::vector<Index> root_label(nv, -1);
  m_face_component.resize(nf);
  for (Index f = 0; f < nf; ++f) {
    const Index r = find_root(parent, m_faces(f, 0));
    if (root_label[r] < 0) root_label[r] = m_num_components++;
    m_face_component[f] = root_label[r];
  }
}

std::span<const Index> TriangleMesh::edge_faces(Index e) const {
  return {m_edge_face_ids.data() + m_edge_face_offsets[e],
          static_cast<std::size_t>(m_edge_face_offsets[e + 1] - m_edge_face_offsets[e])};
}

std::span<const Index> TriangleMesh::vertex_faces(Index v) const {
  return {m_vertex_face_ids.data() + m_vertex_face_offsets[v],
          static_cast<std::size_t>(m_vertex_face_offsets[v + 1] - m_vertex_face_offsets[v])};
}

std::vector<Index> TriangleMesh::vertex_edges(Index v) const {
  // Edges (a, v), a < v: the range of v's larger-vertex edges; edges (v, b), b > v: sides
  // of v's faces.
  std::vector<Index> edges;
  for (Index e = m_edge_end_offsets[v]; e < m_edge_end_offsets[v + 1]; ++e) edges.push_back(e);
  const std::size_t ending_here = edges.size();
  for (Index f : vertex_faces(v)) {
    for (Index e : face_edges(f)) {
      if (m_edges(e, 0) == v) edges.push_back(e);
    }
  }
  std::sort(edges.begin() + static_cast<std::ptrdiff_t>(ending_here), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

std::span<const Index> TriangleMesh::boundary_loop(Index i) const {
  return {m_loop_vertices.data() + m_loop_offsets[i],
          static_cast<std::size_t>(m_loop_offsets[i + 1] - m_loop_offsets[i])};
}

Index TriangleMesh::find_edge(Index a, Index b) const {
  if (a < 0 || b < 0 || a >= m_num_vertices || b >= m_num_vertices || a == b) return -1;
  const Index lo = std::min(a, b), hi = std::max(a, b);
  // The edges (a, hi) are a contiguous range sorted by a: binary search for a = lo.
  // (By hand: clang 14 cannot compile libstdc++ 12's views::iota for ranges::lower_bound.)
  Index begin = m_edge_end_offsets[hi], end = m_edge_end_offsets[hi + 1];
  while (begin < end) {
    const Index mid = begin + (end - begin) / 2;
    if (m_edges(mid, 0) < lo) {
      begin = mid + 1;
    } else {
      end = mid;
    }
  }
  if (begin < m_edge_end_offsets[hi + 1] && m_edges(begin, 0) == lo) return begin;
  return -1;
}

bool TriangleMesh::faces_share_vertex(Index f, Index g) const {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (m_faces(f, i) == m_faces(g, j)) return true;
    }
  }
  return false;
}

}  // namespace tailor
